rotate([90, 0, 0]) cylinder(h = 3, r = 0.5, center = true);
