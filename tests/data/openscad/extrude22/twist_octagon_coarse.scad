$fn = 96;
linear_extrude(height = 3, twist = 100, slices = 2) circle(4, $fn = 8);
