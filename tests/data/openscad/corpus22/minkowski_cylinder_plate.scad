// a plate with rounded vertical edges: minkowski of a cube and a cylinder
minkowski() { translate([0, 0, 0]) cube([40, 25, 2]); cylinder(h = 1, r = 3, $fn = 96); }
