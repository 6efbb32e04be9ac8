// cylinders of different radii and heights and a frustum on parallel axes
hull() {
  cylinder(r = 10, h = 3);
  translate([30, 0, 0]) cylinder(r = 4, h = 12);
  translate([15, 20, 0]) cylinder(r1 = 6, r2 = 2, h = 8);
}
