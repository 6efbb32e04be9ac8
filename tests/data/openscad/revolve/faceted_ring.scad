// A heptagon turned in 5 sections ($fn = 5 on the turn, 7 on the circle).
rotate_extrude($fn = 5) translate([6, 0]) circle(r = 2, $fn = 7);
