cylinder(h=10, r=3);
