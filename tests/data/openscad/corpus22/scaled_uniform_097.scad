linear_extrude(height = 20, scale = [0.97, 0.97]) difference() { square(10, center = true); circle(r = 2); }
