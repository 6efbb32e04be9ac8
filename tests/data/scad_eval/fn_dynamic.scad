module ball(r) sphere(r);
ball(2, $fn = 9);
translate([4, 0, 0]) ball(1);
union($fn = 5) { sphere(1); cylinder(h = 2, r = 0.5); }
