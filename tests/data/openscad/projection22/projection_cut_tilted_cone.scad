// an oblique cut of a frustum: an ellipse
linear_extrude(height = 3) projection(cut = true)
  rotate([25, 10, 0]) cylinder(h = 20, r1 = 8, r2 = 2, center = true);
