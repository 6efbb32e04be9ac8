// a plate with different corner radii: parallel cylinders of different radii between two planes
hull() {
  cylinder(r = 5, h = 3);
  translate([40, 0, 0]) cylinder(r = 2, h = 3);
  translate([40, 25, 0]) cylinder(r = 8, h = 3);
  translate([0, 25, 0]) cylinder(r = 3, h = 3);
}
