name = "part";
if (name == "part") cube(1); else sphere(1);
if (len(name) > 3) translate([2, 0, 0]) cube(len(name));
