// An explicit small $fn: OpenSCAD's hexagonal ring.
rotate_extrude($fn = 6) translate([5, 0]) square([2, 3]);
