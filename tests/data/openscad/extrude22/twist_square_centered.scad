$fn = 96;
linear_extrude(height = 10, twist = 90, slices = 12) square(4, center = true);
