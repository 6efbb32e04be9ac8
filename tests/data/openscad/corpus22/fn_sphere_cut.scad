difference() { sphere(r = 5, $fn = 10); translate([0, 0, 13]) cube(20, center = true); }
