// two spheres of different radii: the spheres and their tangent cone
hull() { sphere(r = 5); translate([12, 4, 3]) sphere(r = 2); }
