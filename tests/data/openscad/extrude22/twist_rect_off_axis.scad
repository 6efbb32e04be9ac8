$fn = 96;
linear_extrude(height = 10, twist = -120) square([3, 2]);
