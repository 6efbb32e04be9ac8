// round solids: isocsg measures the exact box, OpenSCAD its 96-gon's (within its tessellation error)
resize([20, 0, 0], auto = true) sphere(r = 5);
translate([30, 0, 0]) resize([10, 10, 20]) cylinder(h = 5, r = 4);
translate([0, 30, 0]) resize([24, 0, 0], auto = true) difference() { sphere(r = 10); translate([0, 0, 15]) cube(20, center = true); }
