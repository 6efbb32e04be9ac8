translate([1, 2]) cube(1);
translate([0.1, 0.2, 0.3]) translate([-1, 0, 0]) sphere(1);
