color("steelblue") render(convexity = 2)
    difference() {
        cube([3, 2, 1]);
        translate([1.5, 1, -0.5]) cylinder(h = 2, r = 0.6);
    }
