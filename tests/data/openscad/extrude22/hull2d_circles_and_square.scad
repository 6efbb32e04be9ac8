$fn = 96;
linear_extrude(height = 1.5, twist = 20, slices = 4) hull() { square([6, 2]); translate([3, 6]) circle(2.5); translate([-2, 4]) circle(0.5); }
