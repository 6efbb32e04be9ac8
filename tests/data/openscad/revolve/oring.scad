// An O-ring: a circle clear of the axis (a torus).
rotate_extrude() translate([20, 0]) circle(r = 2.5);
