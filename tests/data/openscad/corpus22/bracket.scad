union() { cube([40, 30, 8]); translate([0, 0, 8]) cube([40, 6, 30]); translate([10, 6, 8]) rotate([90, 0, 90]) linear_extrude(height = 4) polygon([[0, 0], [20, 0], [0, 20]]); }
