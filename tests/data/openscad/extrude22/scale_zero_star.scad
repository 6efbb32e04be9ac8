$fn = 96;
linear_extrude(height = 6, scale = 0) polygon([for (i = [0 : 9]) let(r = i % 2 == 0 ? 5 : 2) [r * cos(36 * i), r * sin(36 * i)]]);
