// a pipe elbow: a tube revolved through 90 degrees
rotate_extrude(angle = 90, $fn = 96) translate([20, 0]) difference() { circle(r = 5, $fn = 96); circle(r = 4, $fn = 96); }
