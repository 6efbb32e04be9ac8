for (i = [0:3]) translate([i * 2, 0, 0]) cube(1);
