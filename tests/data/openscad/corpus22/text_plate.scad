difference() { cube([60, 20, 3]); translate([5, 5, 2]) linear_extrude(height = 2) text("ISO", size = 10, font = "DejaVu Sans", $fn = 0); }
