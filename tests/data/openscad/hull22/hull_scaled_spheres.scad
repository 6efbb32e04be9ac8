// a hull of spheres under a scale: ellipsoids of one shape
scale([1, 1, 0.5]) hull() {
  sphere(r = 3);
  translate([10, 0, 0]) sphere(r = 3);
  translate([0, 8, 2]) sphere(r = 3);
}
