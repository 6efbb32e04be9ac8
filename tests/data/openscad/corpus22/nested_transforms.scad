translate([5, 0, 0]) rotate(15) translate([0, 3, 0]) rotate([0, 0, 20]) scale(1.5) translate([1, 1, 0]) linear_extrude(height = 2) polygon([[0, 0], [3, 0], [3, 1], [1, 1], [1, 3], [0, 3]]);
