sphere(d = 10, $fn = 12);
