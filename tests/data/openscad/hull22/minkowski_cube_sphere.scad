// a rounded box: a cube plus a sphere
minkowski() { cube([10, 6, 4], center = true); sphere(r = 1.5); }
