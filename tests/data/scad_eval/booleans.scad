difference() { cube(10, center = true); sphere(6); for (a = [0:90:270]) rotate([0, 0, a]) translate([5, 0, 0]) cylinder(h = 20, r = 1, center = true); }
intersection() { cube(4); sphere(5); }
hull() { cube(1); translate([3, 3, 3]) sphere(1); }
union() { cube(1); }
