// the docs' CSG example: a cube with a spherical bite
difference() {
    cube(2, center = true);
    translate([1, 1, 1]) sphere(r = 0.8);
}
