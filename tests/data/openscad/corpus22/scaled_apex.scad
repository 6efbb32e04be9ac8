linear_extrude(height = 5, scale = 0) polygon([[-3, -3], [3, -3], [0, 4]]);
