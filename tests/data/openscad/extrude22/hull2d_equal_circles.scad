$fn = 96;
linear_extrude(height = 2) hull() { for (p = [[0, 0], [10, 0], [4, 7]]) translate(p) circle(2); }
