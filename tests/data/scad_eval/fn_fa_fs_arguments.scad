sphere(2, $fn = 7); sphere(r = 1, $fa = 5, $fs = 0.5);
cylinder(h = 1, r1 = 2, r2 = 0, $fn = 4);
