// a twisted, scaled, centred extrusion of a non-convex outline with a hole
linear_extrude(height = 20, center = true, twist = 90, slices = 12, scale = 0.6)
    polygon(points = [[-10, -10], [10, -10], [10, 10], [0, 4], [-10, 10], [-4, -4], [4, -4], [4, 2], [-4, 2]], paths = [[0, 1, 2, 3, 4], [5, 6, 7, 8]]);
