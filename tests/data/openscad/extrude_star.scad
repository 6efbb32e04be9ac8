// a five-pointed star from a list comprehension
points = [for (i = [0:9]) let(r = (i % 2 == 0) ? 2 : 0.8) [r * cos(90 + 36 * i), r * sin(90 + 36 * i)]];
linear_extrude(height = 0.6) polygon(points);
