union() { cube(5); *translate([10, 0, 0]) cube(5); translate([0, 0, 5]) cylinder(h = 3, r = 2); }
