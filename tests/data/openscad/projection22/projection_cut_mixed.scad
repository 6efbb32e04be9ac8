// a sphere minus a tilted cylinder and a box, cut through: arcs and an ellipse
linear_extrude(height = 4) projection(cut = true) difference() {
  sphere(r = 12);
  rotate([0, 40, 0]) cylinder(h = 40, r = 4, center = true);
  translate([6, 6, 0]) rotate([0, 0, 30]) cube([8, 8, 8], center = true);
}
