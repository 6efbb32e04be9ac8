// the OpenSCAD logo: a sphere bored through along the three axes
difference() {
    sphere(r = 1);
    cylinder(h = 2.2, r = 0.5, center = true);
    rotate([90, 0, 0]) cylinder(h = 2.2, r = 0.5, center = true);
    rotate([0, 90, 0]) cylinder(h = 2.2, r = 0.5, center = true);
}
