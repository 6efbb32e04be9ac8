// explicit small $fn: a triangular prism, a heptagonal sphere, a square-based pyramid, an octagonal disc
union() {
    cylinder(h = 5, r = 4, $fn = 3);
    translate([12, 0, 0]) sphere(r = 4, $fn = 7);
    translate([0, 12, 0]) cylinder(h = 6, r1 = 5, r2 = 0, $fn = 4);
    translate([12, 12, 0]) linear_extrude(height = 2) circle(r = 5, $fn = 8);
}
