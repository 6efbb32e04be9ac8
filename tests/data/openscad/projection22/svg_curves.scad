// Bezier curves and arcs in OpenSCAD's chords; a unitless page at dpi = 96, centred
linear_extrude(height = 2) import("svg_curves.svg", dpi = 96, center = true);
translate([0, 80, 0]) linear_extrude(height = 2) import("svg_curves.svg");
