sphere(10);
