// a height field from a DAT file
surface(file = "field.dat");
