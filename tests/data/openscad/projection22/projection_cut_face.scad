// faces lying in the plane z = 0 belong to the section, whichever side the solid is on
linear_extrude(height = 2) projection(cut = true) cube(10);
translate([20, 0, 0]) linear_extrude(height = 2) projection(cut = true)
  union() { translate([0, 0, -10]) cube(10); translate([5, 0, 0]) cube(10); }
translate([40, 0, 0]) linear_extrude(height = 2) projection(cut = true) translate([0, 0, -4.999999]) cube(10, center = true);
