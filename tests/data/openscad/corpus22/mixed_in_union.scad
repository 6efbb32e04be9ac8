union() { translate([0, 0, 1]) cube([4, 4, 2]); circle(r = 10); }
