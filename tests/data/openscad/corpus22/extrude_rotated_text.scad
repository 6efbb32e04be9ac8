rotate([90, 0, 0]) linear_extrude(height = 1) text("O", size = 6, font = "DejaVu Sans", $fn = 0);
