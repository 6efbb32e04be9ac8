for (a = [0:15:360]) translate([cos(a) * 10, sin(a) * 10, tan(a == 90 || a == 270 ? 0 : a)]) cube(1);
