a = [1, 2, 3]; b = [0.5, -1, 2];
translate(a + b) cube(a * 2);
translate(a - b) cube(b * -1 + [2, 3, 0] / 2 + [1, 1, 1]);
translate(3 * a) sphere(2);
