module bolt(l) { sphere(1); cylinder(h = l, r = 0.5); }
