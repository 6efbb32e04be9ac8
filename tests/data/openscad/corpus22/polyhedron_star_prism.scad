// a non-convex polyhedron: a five-pointed star prism (faces clockwise seen from outside, as OpenSCAD asks)
n = 5;
pts = [for (i = [0 : 2 * n - 1]) let(r = i % 2 == 0 ? 10 : 4, a = 90 + 180 * i / n) [r * cos(a), r * sin(a)]];
polyhedron(
    points = concat([for (p = pts) [p[0], p[1], 0]], [for (p = pts) [p[0], p[1], 3]], [[0, 0, 0], [0, 0, 3]]),
    faces = concat(
        [for (i = [0 : 2 * n - 1]) [2 * n + i, 2 * n + (i + 1) % (2 * n), (i + 1) % (2 * n), i]],
        [for (i = [0 : 2 * n - 1]) [4 * n, i, (i + 1) % (2 * n)]],
        [for (i = [0 : 2 * n - 1]) [4 * n + 1, 2 * n + (i + 1) % (2 * n), 2 * n + i]]
    )
);
