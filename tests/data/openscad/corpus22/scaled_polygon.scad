linear_extrude(height = 6, scale = 2, center = true) polygon([[0, 0], [4, 0], [4, 1], [1, 1], [1, 4], [0, 4]]);
