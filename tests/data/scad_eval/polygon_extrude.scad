linear_extrude(height = 3) polygon([[0, 0], [4, 0], [2, 3]]);
linear_extrude(5, center = true, twist = 90, slices = 8) square(2, center = true);
linear_extrude(height = 2, scale = [2, 0.5], $fn = 16) circle(1);
linear_extrude(height = 1, scale = 0.5) polygon(points = [[0, 0], [3, 0], [3, 3], [0, 3], [1, 1], [2, 1], [2, 2], [1, 2]], paths = [[0, 1, 2, 3], [4, 5, 6, 7]]);
