// hull of two polyhedra and a cube
hull() {
    polyhedron(points = [[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10]], faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]);
    translate([12, 12, 0]) polyhedron(points = [[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0], [2, 2, 6]], faces = [[0, 3, 2, 1], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]);
    translate([-3, 8, 8]) cube(2);
}
