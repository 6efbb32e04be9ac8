mirror([1, 0, 0]) cube(1);
mirror([1, 1, 0]) cube(1);
mirror([0, 1]) cube(1);
scale(2) cube(1);
scale([1, 2, 3]) sphere(1);
scale([2, 0.5]) cube(1);
