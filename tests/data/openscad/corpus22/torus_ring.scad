// a ring: a revolved circle (a torus) with a flat base cut away
difference() {
    rotate_extrude($fn = 96) translate([12, 0]) circle(r = 3, $fn = 96);
    translate([-20, -20, -5]) cube([40, 40, 3]);
}
