$fn = 96;
linear_extrude(height = 1) hull() { circle(5); translate([1, 1]) circle(2); }
