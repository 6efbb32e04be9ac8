// a knob: a revolved profile with grip notches and an engraved arrow and label
difference() {
    rotate_extrude($fn = 96) polygon([[0, 0], [15, 0], [15, 8], [12, 12], [0, 12]]);
    for (a = [0 : 30 : 330]) rotate([0, 0, a]) translate([15, 0, -1]) cylinder(h = 7, r = 1.5, $fn = 96);
    translate([0, 0, 11]) linear_extrude(height = 2) text("V", size = 8, font = "DejaVu Sans", halign = "center", valign = "center", $fn = 0);
    translate([0, 0, -1]) cylinder(h = 8, r = 3, $fn = 96);
}
