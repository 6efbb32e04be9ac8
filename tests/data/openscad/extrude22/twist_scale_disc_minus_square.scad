$fn = 96;
linear_extrude(height = 6, twist = 30, scale = 0.8, slices = 6) difference() { circle(5); square(2, center = true); }
