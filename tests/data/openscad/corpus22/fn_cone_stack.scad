union() { cylinder(h = 2, r1 = 4, r2 = 4, $fn = 3); translate([0, 0, 2]) cylinder(h = 3, r1 = 4, r2 = 1, $fn = 3); }
