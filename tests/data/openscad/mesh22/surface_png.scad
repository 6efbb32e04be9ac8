// a height map from a PNG image, scaled down in z
scale([1, 1, 0.05]) surface(file = "grey.png");
