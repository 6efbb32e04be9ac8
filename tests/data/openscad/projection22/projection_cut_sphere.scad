// the section of a sphere off its centre: a disc of radius 8
linear_extrude(height = 5) projection(cut = true) translate([0, 0, 6]) sphere(r = 10);
