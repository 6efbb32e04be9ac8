// a ring read from an OFF file, cut by a box
difference() {
  import("ring.off");
  translate([0, -10, 0]) cube([10, 20, 10]);
}
