// a non-convex first operand: each convex piece grown by the sphere
minkowski() { union() { cube([10, 2, 2]); cube([2, 10, 2]); } sphere(r = 1); }
