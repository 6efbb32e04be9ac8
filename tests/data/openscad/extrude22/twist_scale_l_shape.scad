$fn = 96;
linear_extrude(height = 6, twist = 60, scale = 0.6) polygon([[0, 0], [4, 0], [4, 1], [1, 1], [1, 4], [0, 4]]);
