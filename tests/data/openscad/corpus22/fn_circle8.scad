linear_extrude(height = 3) circle(r = 5, $fn = 8);
