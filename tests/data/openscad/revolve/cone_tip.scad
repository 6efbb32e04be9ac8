// A profile touching the axis: a cone, and a cup (a polygon with an edge on the axis).
rotate_extrude() polygon([[0, 0], [5, 0], [0, 8]]);
translate([20, 0, 0]) rotate_extrude() polygon([[0, 0], [6, 0], [6, 6], [5, 6], [5, 1], [0, 1]]);
