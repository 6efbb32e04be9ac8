rotate([0, 90, 0]) cylinder(h = 10, d = 8, $fn = 6, center = true);
