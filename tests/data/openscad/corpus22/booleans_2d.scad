linear_extrude(height = 2) difference() { union() { square(8); translate([4, 4]) circle(r = 4); } intersection() { square(6, center = true); rotate(45) square(6, center = true); } }
