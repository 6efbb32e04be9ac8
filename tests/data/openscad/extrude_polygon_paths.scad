// a frame: the second path is a hole (even-odd fill)
linear_extrude(height = 1)
    polygon(points = [[0, 0], [4, 0], [4, 3], [0, 3], [1, 1], [3, 1], [3, 2], [1, 2]],
            paths = [[0, 1, 2, 3], [4, 5, 6, 7]]);
