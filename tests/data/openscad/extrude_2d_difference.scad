linear_extrude(height = 0.8)
    difference() {
        square(4, center = true);
        circle(r = 1);
        translate([1.5, 1.5]) square(0.6, center = true);
    }
