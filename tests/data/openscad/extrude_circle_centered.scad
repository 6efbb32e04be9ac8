linear_extrude(height = 3, center = true) circle(r = 1);
