b = 2; translate([b, 0, 0]) cube(1);
