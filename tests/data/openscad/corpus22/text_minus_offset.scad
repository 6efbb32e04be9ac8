linear_extrude(height = 1) difference() { offset(r = 1.5) square([30, 12]); translate([2, 2]) text("HI", size = 8, font = "DejaVu Sans", $fn = 0); }
