// A square with a round notch, turned: a 2D difference.
rotate_extrude() difference() {
  translate([5, -5]) square([10, 10]);
  translate([10, 0]) circle(r = 3);
}
