rotate([30, 45, 60]) cube([1, 2, 3], center = true);
