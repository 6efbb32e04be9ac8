for (a = [7.3, 123.4, -45.6, 1000.1]) rotate(a) translate([cos(a), sin(a), 0]) cube([1, 2, 3]);
