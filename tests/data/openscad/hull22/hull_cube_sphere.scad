// a cube and a sphere above it: the cube's corners are balls of radius 0 (cones to the sphere)
hull() {
  cube(10, center = true);
  translate([0, 0, 12]) sphere(r = 4);
}
