$fn = 96;
linear_extrude(height = 3) hull() { circle(3); translate([12, 5]) circle(1); }
