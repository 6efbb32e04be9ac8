// a capsule lid: hull of four equal spheres, beside a hull of two parallel cylinders
union() {
    hull() for (x = [0, 20], z = [0, 10]) translate([x, 0, z]) sphere(r = 4, $fn = 96);
    translate([0, 15, 0]) hull() { cylinder(h = 10, r = 4, $fn = 96); translate([20, 0, 0]) cylinder(h = 10, r = 4, $fn = 96); }
}
