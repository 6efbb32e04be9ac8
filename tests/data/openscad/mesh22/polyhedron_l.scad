// a non-convex polyhedron: an L-shaped prism with polygon faces (clockwise seen from outside)
polyhedron(
  points = [[0, 0, 0], [4, 0, 0], [4, 1, 0], [1, 1, 0], [1, 3, 0], [0, 3, 0],
            [0, 0, 2], [4, 0, 2], [4, 1, 2], [1, 1, 2], [1, 3, 2], [0, 3, 2]],
  faces = [[0, 1, 2, 3, 4, 5], [11, 10, 9, 8, 7, 6],
           [6, 7, 1, 0], [7, 8, 2, 1], [8, 9, 3, 2], [9, 10, 4, 3], [10, 11, 5, 4], [11, 6, 0, 5]]);
