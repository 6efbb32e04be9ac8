// the same height field, centred, intersected with a cylinder
intersection() {
  translate([0, 0, -5]) surface(file = "field.dat", center = true);
  cylinder(r = 2.5, h = 20, center = true, $fn = 6);
}
