linear_extrude(height = 10, scale = 0.5) square([6, 4], center = true);
