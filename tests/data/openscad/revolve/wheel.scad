// A wheel: a tyre (torus), a rim (rectangle) and a hub with a bore, unioned, then drilled.
difference() {
  union() {
    rotate_extrude() translate([18, 0]) circle(r = 3);
    rotate_extrude() translate([4, -2]) square([13, 4]);
  }
  for (a = [0 : 60 : 300]) rotate([0, 0, a]) translate([11, 0, -5]) cylinder(r = 2.5, h = 10);
}
