linear_extrude(height = 1) rotate(30) square([2, 1]);
