// a base plate and two domes of different radii
hull() {
  cube([30, 16, 2]);
  translate([10, 8, 7]) sphere(r = 6);
  translate([24, 8, 4]) sphere(r = 3);
}
