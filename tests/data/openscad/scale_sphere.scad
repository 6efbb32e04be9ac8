// an ellipsoid
scale([1, 2, 0.5]) sphere(r = 1);
