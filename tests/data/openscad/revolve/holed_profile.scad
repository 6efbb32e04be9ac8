// A polygon with a hole (two paths) turned: a hollow ring.
rotate_extrude() polygon(points = [[5, 0], [15, 0], [15, 20], [5, 20], [8, 5], [12, 5], [12, 15], [8, 15]],
                         paths = [[0, 1, 2, 3], [4, 5, 6, 7]]);
