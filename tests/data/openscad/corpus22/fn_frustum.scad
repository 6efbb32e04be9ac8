cylinder(h = 4, r1 = 3, r2 = 1.5, $fn = 5, center = true);
