linear_extrude(height = 2) offset(delta = 1, chamfer = true) square([8, 4], center = true);
