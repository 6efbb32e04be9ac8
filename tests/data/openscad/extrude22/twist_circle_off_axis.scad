$fn = 96;
linear_extrude(height = 8, twist = 180) translate([4, 0]) circle(1.5);
