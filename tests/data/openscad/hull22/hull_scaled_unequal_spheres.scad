// spheres of different radii under one scale: ellipsoids of one shape and different sizes
scale([2, 1, 0.7]) hull() {
  sphere(r = 3);
  translate([5, 5, 0]) sphere(r = 1);
  translate([0, 6, 4]) sphere(r = 2);
  translate([-2, 1, 6]) sphere(r = 0.5);
}
