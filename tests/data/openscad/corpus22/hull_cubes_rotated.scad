// hull of rotated and scaled cubes: a convex polyhedron
hull() {
    cube([10, 10, 2], center = true);
    translate([0, 0, 12]) rotate([0, 0, 45]) scale([0.5, 0.5, 1]) cube([10, 10, 2], center = true);
    translate([8, 0, 6]) rotate([30, 20, 10]) cube(3, center = true);
}
