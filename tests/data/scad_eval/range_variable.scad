r = [1:3];
for (i = r) translate([i, 0, 0]) cube(0.5);
for (i = [0:2:9]) translate([0, i, 0]) cube(0.5);
