cylinder(h = 3, r1 = 1.2, r2 = 0.4, center = true);
