// A clockwise turn of 120 degrees (a negative angle) of a triangle.
rotate_extrude(angle = -120) polygon([[3, 0], [9, 0], [5, 7]]);
