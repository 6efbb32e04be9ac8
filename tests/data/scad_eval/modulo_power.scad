for (i = [0:7]) translate([i % 3, 2 ^ (i % 4), -i ^ 2 / 10]) cube(0.5);
