linear_extrude(height = 2) polygon(points = [[0, 0], [10, 0], [10, 10], [0, 10], [2, 2], [8, 2], [8, 8], [2, 8]], paths = [[0, 1, 2, 3], [4, 5, 6, 7]]);
