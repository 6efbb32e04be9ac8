linear_extrude(height = 3, center = true) polygon([[0, 0], [10, 0], [10, 10], [5, 3], [0, 10]]);
