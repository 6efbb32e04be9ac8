sphere(r = 1.5);
