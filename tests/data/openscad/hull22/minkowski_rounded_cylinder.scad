// a rounded disc: a cylinder plus a sphere (two cylinders and two tori)
minkowski() { cylinder(r = 10, h = 4); sphere(r = 1.5); }
