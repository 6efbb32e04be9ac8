linear_extrude(height = 1) polygon(points = [[0, 0], [4, 0], [4, 4], [0, 4], [6, 0], [9, 0], [9, 3]], paths = [[0, 1, 2, 3], [4, 5, 6]]);
