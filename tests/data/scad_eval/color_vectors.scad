color([1, 0, 0]) cube(1);
color([0.2, 0.4, 0.6, 0.8]) sphere(1);
color([0.1, 0.3, 0.7], 0.5) cylinder(h = 1, r = 1);
color(c = [0.33, 0.66, 0.99]) cube(2);
