// spaced lettering, centred on both axes, on a plate
union() {
    translate([-25, -8, -2]) cube([50, 16, 2]);
    linear_extrude(height = 1.2) text("OK 7", size = 7, font = "DejaVu Sans", spacing = 1.3, halign = "center", valign = "center", $fn = 0);
}
