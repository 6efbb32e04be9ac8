linear_extrude(height = 1.5) text("Ag", size = 8, font = "DejaVu Sans", $fn = 0, halign = "center", valign = "center");
