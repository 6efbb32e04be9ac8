function ring(z, r, n) = [for (i = [0:n - 1]) [r * cos(360 * i / n), r * sin(360 * i / n), z]];
n = 6;
pts = [each ring(0, 2, n), each ring(3, 1, n)];
faces = [[for (i = [n - 1:-1:0]) i], [for (i = [n:2 * n - 1]) i], for (i = [0:n - 1]) [i, (i + 1) % n, n + (i + 1) % n, n + i]];
polyhedron(points = pts, faces = faces);
