linear_extrude(height = 4) difference() { circle(r = 10, $fn = 8); circle(r = 4, $fn = 6); }
