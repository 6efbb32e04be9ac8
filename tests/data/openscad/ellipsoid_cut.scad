difference() {
    scale([1.5, 1, 0.7]) sphere(r = 1);
    translate([0, 0, 0.5]) cube([4, 4, 1], center = true);
}
