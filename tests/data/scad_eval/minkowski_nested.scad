module rounded(r) minkowski() { children(); sphere(r, $fn = 8); }
rounded(0.5) cube([3, 2, 1]);
translate([5, 0, 0]) minkowski() { minkowski() { cube(1); cube(2); } for (i = [0:1]) sphere(i + 1); }
