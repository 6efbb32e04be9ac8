cylinder(h = 2, r = 1);
