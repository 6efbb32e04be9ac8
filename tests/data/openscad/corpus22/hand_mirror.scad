union() { translate([2, 0, 0]) cube([3, 1, 1]); mirror([1, 0, 0]) translate([2, 0, 0]) cylinder(h = 1, r = 0.5); }
