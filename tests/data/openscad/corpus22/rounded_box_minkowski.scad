// a rounded block via minkowski of a cube and a sphere, with a square pocket
difference() {
    minkowski() { cube([30, 20, 8]); sphere(r = 2, $fn = 96); }
    translate([5, 5, 4]) cube([20, 10, 10]);
}
