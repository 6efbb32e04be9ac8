// a rounded box: the hull of eight spheres of one radius
hull() { for (x = [0, 20], y = [0, 12], z = [0, 6]) translate([x, y, z]) sphere(r = 2); }
