difference() { cylinder(h = 5, r = 6, $fn = 6); translate([0, 0, -1]) cylinder(h = 7, r = 3); }
