// a bar with a row of M3 bolt holes and hexagonal nut traps ($fn = 6)
difference() {
    cube([60, 12, 8]);
    for (i = [0 : 4]) translate([6 + 12 * i, 6, 0]) {
        translate([0, 0, -1]) cylinder(h = 10, d = 3.2, $fn = 24);
        translate([0, 0, -1]) cylinder(h = 3.5, d = 6.4, $fn = 6);
    }
}
