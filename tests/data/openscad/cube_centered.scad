// cube(size, center): the docs' first example
cube([2, 3, 1], center = true);
