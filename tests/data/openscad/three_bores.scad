// a block bored along the three axes
difference() {
    cube(2, center = true);
    cylinder(h = 3, r = 0.6, center = true);
    rotate([90, 0, 0]) cylinder(h = 3, r = 0.5, center = true);
    rotate([0, 90, 0]) cylinder(h = 3, r = 0.4, center = true);
}
