// coloured parts of an assembly: colours change nothing of the solid
color("red") cube([20, 10, 4]);
color([0, 0.5, 1, 0.6]) translate([10, 5, 4]) cylinder(h = 6, r = 4, $fn = 96);
color("green") translate([3, 3, 4]) sphere(r = 2.5, $fn = 96);
