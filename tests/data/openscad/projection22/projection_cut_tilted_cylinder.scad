// an oblique cut of a cylinder: an ellipse, clipped by one end
linear_extrude(height = 2) projection(cut = true)
  translate([0, 0, -3]) rotate([50, 0, 20]) cylinder(h = 12, r = 5);
