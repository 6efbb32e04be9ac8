// a box with rounded vertical edges: a cube plus a cylinder
minkowski() { cube([10, 6, 2]); cylinder(r = 2, h = 1); }
