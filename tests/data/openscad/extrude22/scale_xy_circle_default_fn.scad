// OpenSCAD's defaults: $fa = 12, $fs = 2 (a 13-gon, ceil(hypot(4, 4) / 2) = 3 slices)
linear_extrude(height = 4, scale = [0.5, 2]) circle(4);
