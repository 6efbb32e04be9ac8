$fn = 96;
linear_extrude(height = 5, scale = [2, 0.5], slices = 6) polygon([[0, 0], [5, 0], [5, 3], [3, 1], [0, 3]]);
