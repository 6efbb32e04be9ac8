// a non-convex polyhedron: a cube with a pyramid pushed into its bottom, minus a sphere
difference() {
  polyhedron(points = [[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0], [1, 1, 0.5], [0, 0, 2], [2, 0, 2], [2, 2, 2], [0, 2, 2]],
    faces = [[0, 4, 1], [1, 4, 2], [2, 4, 3], [3, 4, 0], [5, 6, 7, 8], [0, 1, 6, 5], [1, 2, 7, 6], [2, 3, 8, 7], [3, 0, 5, 8]]);
  translate([2, 2, 2]) sphere(r = 0.8, $fn = 96);
}
