cube(); cube(2); cube([1, 2, 3], true); cube(size = 4, center = false);
square(); square(2); square([1, 3], center = true);
