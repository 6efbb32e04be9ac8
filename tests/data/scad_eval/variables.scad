a = 2; b = a * 3 + 1; c = [a, b, -a / 4];
translate(c) cube([a, b, 0.5]);
