linear_extrude(height = 6, scale = 0.5) translate([3, 1]) circle(r = 2);
