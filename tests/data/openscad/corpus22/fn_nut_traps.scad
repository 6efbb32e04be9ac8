difference() { cube([40, 12, 6]); for (i = [0 : 3]) translate([5 + 10 * i, 6, 3]) cylinder(h = 4, r = 3.2, $fn = 6); }
