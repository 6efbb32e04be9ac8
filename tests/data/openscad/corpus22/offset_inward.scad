linear_extrude(height = 4) offset(r = -1) square([10, 10]);
