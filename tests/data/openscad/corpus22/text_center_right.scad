linear_extrude(height = 2, center = true) text("42", size = 12, font = "DejaVu Sans:style=Bold", halign = "right", valign = "top", $fn = 0);
