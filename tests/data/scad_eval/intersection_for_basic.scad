intersection_for (i = [0:2]) rotate(i * 30) cube(5, center = true);
intersection_for (a = [[1, 2, 3], [2, 1, 3]]) cube(a);
