// A hexagonal turn ($fn = 6) of a round circle ($fn = 200 is above 64: read as the exact disc).
rotate_extrude($fn = 6) translate([5, 0]) circle(r = 1.5, $fn = 200);
