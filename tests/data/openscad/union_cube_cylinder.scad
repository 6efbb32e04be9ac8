union() {
    cube([2, 2, 1]);
    translate([1, 1, 1]) cylinder(h = 1.5, r = 0.6);
}
