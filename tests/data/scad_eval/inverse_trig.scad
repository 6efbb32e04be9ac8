cube([asin(0.5) / 10, acos(0.5) / 10, atan(1) / 10]);
translate([atan2(1, 1), atan2(-1, 2), 0]) sphere(1);
