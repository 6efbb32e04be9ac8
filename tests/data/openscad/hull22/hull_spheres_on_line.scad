// spheres on one line: those on the hull joined by tangent cones, the inner one left out
hull() {
  sphere(r = 3);
  translate([4, 0, 0]) sphere(r = 0.5);
  translate([6, 0, 0]) sphere(r = 1);
  translate([10, 0, 0]) sphere(r = 2.5);
}
