cylinder(2, 1, 3); cylinder(3, 2); cylinder(h = 2, d = 4); cylinder(h = 2, d1 = 4, d2 = 2, center = true);
cylinder(r = 1); cylinder(1, r1 = 0.5, r2 = 1.5);
