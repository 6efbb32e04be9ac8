// a plate with vertical through holes, a sphere cut by a square prism: differences of vertical prisms
linear_extrude(height = 2) projection() difference() {
  translate([0, 0, 1]) rotate([0, 0, 15]) cube([30, 20, 2], center = true);
  translate([5, 0, -5]) cylinder(h = 10, r = 3);
  translate([-7, 3, -5]) cube([4, 4, 10]);
}
translate([40, 0, 0]) linear_extrude(height = 2) projection() difference() {
  sphere(r = 8);
  cube([6, 6, 30], center = true);
}
