// outlines of a plate with through holes, blind holes from both faces, holes meeting from both
// sides, a counterbore, a ball and a cone through it; a stepped part with a blind hole; prisms of
// different heights intersected
linear_extrude(height = 2) projection() difference() {
  cube([40, 30, 4]);
  for (i = [0:3]) translate([5 + 10 * i, 5, -1]) cylinder(h = 6, r = 2);
  for (i = [0:3]) translate([5 + 10 * i, 12, 2]) cylinder(h = 5, r = 2);
  for (i = [0:3]) translate([5 + 10 * i, 19, -1]) cylinder(h = 3, r = 2);
  translate([5, 26, -1]) cylinder(h = 3.5, r = 2);
  translate([6, 26, 2]) cylinder(h = 3, r = 2);
  translate([15, 26, 3]) cylinder(h = 2, r = 3);
  translate([15, 26, -1]) cylinder(h = 6, r = 1);
  translate([28, 26, 1.5]) sphere(r = 3);
  translate([36, 26, -1]) cylinder(h = 6, r1 = 3, r2 = 1);
}
translate([50, 0, 0]) linear_extrude(height = 2) projection() difference() {
  union() {
    cube([20, 20, 2]);
    translate([10, 10, 0]) cylinder(h = 8, r = 6);
  }
  translate([10, 10, 3]) cylinder(h = 10, r = 4);
  translate([3, 3, 1]) cube([4, 4, 4]);
}
translate([80, 0, 0]) linear_extrude(height = 2) projection() intersection() {
  cube([10, 10, 4]);
  translate([10, 10, 2]) cylinder(h = 10, r = 8);
}
