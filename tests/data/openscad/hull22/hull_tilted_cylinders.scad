// parallel cylinders of one radius at different heights, turned: oblique swept discs
rotate([30, 20, 0]) hull() {
  cylinder(r = 2, h = 10);
  translate([8, 0, 3]) cylinder(r = 2, h = 4);
  translate([3, 7, -2]) cylinder(r = 2, h = 6);
}
