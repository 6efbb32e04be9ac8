linear_extrude(height = 2) square([2, 1]);
