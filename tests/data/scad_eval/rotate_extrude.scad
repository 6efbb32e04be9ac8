rotate_extrude($fn = 24) translate([5, 0]) circle(1);
rotate_extrude(angle = 90, convexity = 4) translate([3, 0]) square([1, 2]);
rotate_extrude(angle = 400) translate([2, 0]) circle(0.5);
