// A vase: a non-convex wall profile (3 thick at the base, 1 at the top) turned about z.
rotate_extrude() polygon([[0, 0], [10, 0], [12, 10], [8, 25], [10, 35], [9, 35], [7, 25], [11, 10], [9, 3], [0, 3]]);
