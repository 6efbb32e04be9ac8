hull() { for (x = [0, 10], y = [0, 6]) translate([x, y, 0]) cylinder(h = 2, r = 1.5, $fn = 16); }
