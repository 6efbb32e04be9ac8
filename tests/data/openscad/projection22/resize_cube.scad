// per-axis sizes of a cube and a polyhedron under a map (OpenSCAD's own box: exact)
resize([20, 10, 5]) cube([1, 2, 3]);
translate([30, 0, 0]) resize([0, 0, 8], auto = true) rotate([0, 0, 30]) cube([4, 2, 2]);
translate([0, 30, 0]) resize([12, 0, 0], auto = [false, true, false]) cube([3, 2, 1]);
