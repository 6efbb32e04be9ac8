big = true;
if (big) cube(3); else sphere(1);
if (!big) cube(1);
if (1 > 2) sphere(2); else if (2 > 1) cylinder(h = 2, r = 1);
