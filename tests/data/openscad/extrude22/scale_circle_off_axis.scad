$fn = 96;
linear_extrude(height = 5, scale = 0.4) translate([3, 0]) circle(2);
