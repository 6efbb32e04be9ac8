translate([1, 0, 0], $fn = 5) sphere(1); color([1, 0, 0], $fn = 6) sphere(1);
hull($fn = 7) sphere(1); union($fn = 8) sphere(1); difference($fn = 9) sphere(1);
rotate(5, $fn = 11) sphere(1); linear_extrude(1, $fn = 12) circle(1);
