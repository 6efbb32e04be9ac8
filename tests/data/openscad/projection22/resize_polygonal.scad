// resize of polygonal solids: OpenSCAD's box is the exact one
resize([10, 10, 4]) cylinder(h = 2, r = 3, $fn = 6);
translate([20, 0, 0]) resize([15, 0, 0], auto = true) difference() { cube(10); translate([5, 5, -1]) cylinder(h = 12, r = 3, $fn = 8); }
