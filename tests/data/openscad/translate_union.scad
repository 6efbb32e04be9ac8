cube(1);
translate([2, 0, 0]) sphere(r = 0.5);
translate([0, 2, 0]) cylinder(h = 1, r1 = 0.5, r2 = 0.2);
