// offsets in sequence: a chamfered delta, a rounding inwards, on a notched outline with a hole
linear_extrude(height = 4) offset(r = -1, $fn = 96) offset(delta = 2, chamfer = true)
    polygon(points = [[0, 0], [30, 0], [30, 20], [18, 20], [15, 10], [12, 20], [0, 20], [6, 6], [12, 6], [12, 12], [6, 12]], paths = [[0, 1, 2, 3, 4, 5, 6], [7, 8, 9, 10]]);
