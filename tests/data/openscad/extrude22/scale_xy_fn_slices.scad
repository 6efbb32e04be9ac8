$fn = 96;
linear_extrude(height = 4, scale = [0.5, 1.5], $fn = 7) square([4, 2], center = true);
