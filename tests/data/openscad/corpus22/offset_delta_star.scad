linear_extrude(height = 1) offset(delta = -0.3) polygon([for (i = [0 : 9]) (i % 2 == 0 ? 5 : 2) * [cos(36 * i), sin(36 * i)]]);
