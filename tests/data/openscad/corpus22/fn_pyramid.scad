cylinder(h = 10, r1 = 5, r2 = 0, $fn = 4);
