module post(h) { cylinder(h = h, r = 0.2); }
cube([4, 1, 0.3]);
for (x = [0.5:1:3.5]) translate([x, 0.5, 0.3]) post(0.5 + x / 2);
