// a plate and a post: a cube's corners with a cylinder (discs and points)
hull() {
  cube([20, 10, 2]);
  translate([10, 5, 0]) cylinder(r = 3, h = 15);
}
