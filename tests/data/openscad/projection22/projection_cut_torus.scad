// a torus about z cut off its middle plane: an annulus
linear_extrude(height = 2) projection(cut = true) translate([0, 0, 1]) rotate_extrude() translate([8, 0]) circle(r = 3);
