for (i = []) cube(1);
cube(2);
