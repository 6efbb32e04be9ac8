// a dome on a cylinder with a cone below: trunci on one axis and a sphere centred on it
hull() {
  cylinder(r = 10, h = 4);
  translate([0, 0, 12]) sphere(r = 6);
  translate([0, 0, -6]) cylinder(r1 = 0, r2 = 4, h = 6);
}
