// a non-uniform scale of a rotated cube: a parallelepiped
scale([2, 1, 1]) rotate([0, 0, 45]) cube(1, center = true);
