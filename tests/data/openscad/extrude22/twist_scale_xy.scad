$fn = 96;
linear_extrude(height = 6, twist = 45, scale = [1.5, 0.7], slices = 10) square(3, center = true);
