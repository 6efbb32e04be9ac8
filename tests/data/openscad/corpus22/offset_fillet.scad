linear_extrude(height = 2) offset(r = 1) offset(r = -1) difference() { square(10); square(5); }
