// bold text on the baseline, right aligned, scaled along x
scale([1.5, 1, 1]) linear_extrude(height = 2) text("Ax", size = 9, font = "DejaVu Sans:style=Bold", halign = "right", valign = "baseline", $fn = 0);
