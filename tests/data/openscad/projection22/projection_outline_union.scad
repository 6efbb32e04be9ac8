// OpenSCAD's projection-tests: a cube beside a sphere with a vertical bore through it
linear_extrude(height = 2) projection() {
  cube(10);
  difference() { sphere(10); cylinder(h = 30, r = 5, center = true); }
}
