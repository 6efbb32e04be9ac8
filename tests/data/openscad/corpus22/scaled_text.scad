linear_extrude(height = 3, scale = 1.2) text("T", size = 10, font = "DejaVu Sans", $fn = 0);
