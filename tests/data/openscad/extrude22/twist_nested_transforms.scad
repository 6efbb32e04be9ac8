$fn = 96;
translate([5, 0, 2]) rotate([0, 30, 45]) scale([1, 2, 1]) linear_extrude(height = 7, twist = 75, slices = 15) translate([2, 0]) polygon([[0, 0], [3, 0], [1.5, 2]]);
