// a centred straight extrusion of a frame with two windows
linear_extrude(height = 6, center = true) difference() {
    square([30, 20], center = true);
    translate([-8, 0]) square([10, 12], center = true);
    translate([8, 0]) circle(r = 5, $fn = 7);
}
