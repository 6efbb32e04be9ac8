$fn = 96;
linear_extrude(height = 3, twist = 100, slices = 3) circle(4, $fn = 8);
