// A pulley with a V groove and a bore, placed in an assembly and cut by a key slot.
difference() {
  translate([0, 0, 2]) rotate([0, 0, 30]) rotate_extrude() polygon([[3, 0], [15, 0], [15, 2], [12, 5], [15, 8], [15, 10], [3, 10]]);
  translate([-1, 0, 0]) cube([2, 5, 20]);
}
