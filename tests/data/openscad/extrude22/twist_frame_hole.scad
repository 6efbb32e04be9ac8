$fn = 96;
linear_extrude(height = 5, twist = 45, slices = 9) difference() { square(10, center = true); square(4, center = true); }
