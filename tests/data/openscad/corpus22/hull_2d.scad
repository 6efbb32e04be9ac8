linear_extrude(height = 3) hull() { square(2); translate([8, 0]) square(2); translate([4, 6]) square(1); }
