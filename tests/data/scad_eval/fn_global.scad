$fn = 12;
sphere(2); cylinder(h = 3, r = 1); translate([5, 0, 0]) circle(1);
