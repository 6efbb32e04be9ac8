// an imported bracket, mirrored and joined to a plate with a hole
difference() {
    union() {
        cube([30, 30, 2]);
        translate([0, 0, 2]) import("../mesh22/bracket.stl");
        translate([30, 30, 2]) mirror([1, 0, 0]) mirror([0, 1, 0]) import("../mesh22/bracket.stl");
    }
    translate([15, 15, -1]) cylinder(h = 5, r = 3, $fn = 96);
}
