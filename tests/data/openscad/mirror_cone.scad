mirror([1, 0, 0]) translate([1, 0, 0]) cylinder(h = 2, r1 = 1, r2 = 0);
cube(0.5);
