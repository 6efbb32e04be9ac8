cube([abs(-2), sign(-3) + 2, sqrt(2)]);
translate([pow(2, 3), exp(1), ln(10)]) cube([log(100), log(2, 8), floor(2.7) + ceil(0.2)]);
translate([round(2.5), round(-2.5), min(3, 1, 2)]) cube([max([1, 5, 2]), norm([3, 4]), len([1, 2, 3])]);
