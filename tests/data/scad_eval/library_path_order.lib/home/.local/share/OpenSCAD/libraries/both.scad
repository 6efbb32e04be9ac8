which = 3;
