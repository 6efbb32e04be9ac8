linear_extrude(height = 8, scale = 0.25) circle(r = 4);
