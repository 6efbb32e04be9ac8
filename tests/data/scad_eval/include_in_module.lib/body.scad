k = s * 2;
translate([k, 0, 0]) cube(s);
