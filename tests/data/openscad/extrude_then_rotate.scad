// a triangular wedge lying on its side
rotate([90, 0, 0]) linear_extrude(height = 2) polygon([[0, 0], [2, 0], [0, 1.5]]);
