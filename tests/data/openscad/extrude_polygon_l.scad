linear_extrude(height = 0.5)
    polygon(points = [[0, 0], [3, 0], [3, 1], [1, 1], [1, 2.5], [0, 2.5]]);
