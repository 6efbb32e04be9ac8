// four spheres of different radii, centres off one line: spheres, tangent frusta, a polyhedron
hull() {
  sphere(r = 6);
  translate([20, 3, 0]) sphere(r = 2);
  translate([8, 15, 2]) sphere(r = 3.5);
  translate([6, 5, 12]) sphere(r = 1);
}
