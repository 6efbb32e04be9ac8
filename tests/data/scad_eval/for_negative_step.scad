for (i = [5:-1.5:0]) translate([0, 0, i]) cylinder(h = 1, r = i + 1);
