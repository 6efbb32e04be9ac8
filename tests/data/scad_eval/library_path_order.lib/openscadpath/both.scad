which = 2;
