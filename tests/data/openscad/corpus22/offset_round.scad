linear_extrude(height = 3) offset(r = 2) square([10, 6]);
