for (i = [0:4]) translate([i * 1.2, 0, 0]) cube([1, 1, 0.5 + 0.3 * i]);
