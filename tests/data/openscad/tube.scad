difference() {
    cylinder(h = 2, r = 1);
    translate([0, 0, -1]) cylinder(h = 4, r = 0.7);
}
