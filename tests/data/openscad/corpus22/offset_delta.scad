linear_extrude(height = 2) offset(delta = 1.5) polygon([[0, 0], [10, 0], [5, 8]]);
