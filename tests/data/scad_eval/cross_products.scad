a = cross([1, 2, 3], [4, 5, 6]);
b = cross([0.1, -2.5, 3e3], [7, 0.3, -1]);
c = cross([1, 0, 0], [0, 1, 0]);
d = cross([2, 3], [5, -7]);
translate(a) cube(c + [1, 1, 0]);
translate(b / 1000) sphere(abs(d) / 10);
