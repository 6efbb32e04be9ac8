// A quarter turn of a rectangle.
rotate_extrude(angle = 90) translate([5, 0]) square([3, 6]);
