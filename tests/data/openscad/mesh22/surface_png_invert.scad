// the inverted image, centred
scale([1, 1, 0.02]) surface(file = "grey.png", center = true, invert = true);
