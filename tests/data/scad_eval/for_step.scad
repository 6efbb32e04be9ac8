for (i = [0:0.1:1]) translate([i, i * i, 0]) sphere(0.05, $fn = 6);
