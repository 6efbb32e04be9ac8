// a rounded box moved, turned and scaled: the map applies once to the sum
translate([5, -3, 2]) rotate([0, 0, 90]) scale(1.5) minkowski() { cube([8, 5, 3]); translate([1, 1, 1]) sphere(r = 1); }
