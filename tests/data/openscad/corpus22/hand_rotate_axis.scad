rotate(a = 30, v = [1, 1, 0]) cube([6, 2, 1]);
