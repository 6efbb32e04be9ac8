for (i = [0:2], j = [0:1]) translate([i, j, 0]) cube(0.5);
