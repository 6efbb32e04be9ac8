minkowski() { cube(1); sphere(1); }
minkowski(3) { cube([2, 1, 1]); cylinder(h = 1, r = 0.5); }
minkowski(convexity = 2.7) cube(1);
minkowski($fn = 5) { cube(1); sphere(1); }
minkowski();
