// two convex polyhedra: the hull of the sums of their corners
minkowski() {
  polyhedron(points = [[0, 0, 0], [4, 0, 0], [0, 3, 0], [0, 0, 5]], faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]);
  rotate([10, 20, 30]) cube(2, center = true);
}
