$fn = 96;
linear_extrude(height = 4, center = true, twist = -30, slices = 4) translate([1, 1]) square([2, 3]);
