for (p = [[1, 2, 3], [-1, 0, 2.5], [0, 0, 0]]) translate(p) cube(0.5, center = true);
