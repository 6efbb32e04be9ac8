// hollow cubes (OpenSCAD's projection-cut-tests): sections with holes
linear_extrude(height = 1) projection(cut = true) union() {
  difference() { cube(5, center = true); cube(4, center = true); }
  translate([2.1, 2.1]) difference() { cube(5, center = true); cube(4, center = true); }
}
translate([0, -12, 0]) linear_extrude(height = 1) projection(cut = true)
  difference() { cube(10, center = true); cube([5, 5, 20], center = true); }
