linear_extrude(height = 1.2)
    union() {
        square(2);
        translate([2, 1]) circle(r = 1);
    }
