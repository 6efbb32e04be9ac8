$fn = 96;
linear_extrude(height = 5, twist = 40, slices = 8) union() { square(3); translate([2, 2]) square(3); }
