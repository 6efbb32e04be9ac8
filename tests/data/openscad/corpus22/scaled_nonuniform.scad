linear_extrude(height = 5, scale = [1.5, 0.5]) square([4, 4], center = true);
