// a difference of turned boxes (not the difference of their shadows): flat faces, through manifold3d
linear_extrude(height = 2) projection() difference() {
  rotate([30, 20, 10]) cube(10, center = true);
  rotate([0, 45, 0]) cube([4, 20, 4], center = true);
  translate([0, 0, 6]) cube(6, center = true);
}
