// cylinders of different radii and heights under one scale: elliptic cylinders, one map
scale([1.5, 0.8, 1]) hull() {
  cylinder(r = 6, h = 2);
  translate([20, 5, 0]) cylinder(r = 3, h = 9);
}
