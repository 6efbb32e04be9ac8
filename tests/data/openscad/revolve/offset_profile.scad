// A rounded rectangle (offset r = 1) turned: a tube with filleted edges.
rotate_extrude() offset(r = 1) translate([6, 0]) square([4, 8]);
