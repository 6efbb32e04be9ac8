linear_extrude(height = 2) offset(r = 1) union() { square([6, 2]); translate([3, 1]) circle(r = 2); }
