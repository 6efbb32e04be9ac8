// a plate with rounded corners: the hull of four parallel cylinders
hull() { for (x = [0, 30], y = [0, 18]) translate([x, y, 0]) cylinder(r = 3, h = 4); }
