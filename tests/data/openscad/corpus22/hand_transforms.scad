translate([1, 2, 3]) rotate([30, 45, 60]) scale([1, 2, 0.5]) cube(4, center = true);
