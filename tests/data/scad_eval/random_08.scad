a = -6;
b = sin(-29);
function f(x, y = 2) = x * y + a;
module part(s, t = 9) { translate([cos((abs(150) + 0.5 - s)), cos(abs((180 + 120)) + 0.5), (abs(135) + 0.5 - (a - (12 + s)))]) cylinder(h = abs(cos(270)) + 0.5, r1 = abs(cos((abs(s) + 0.5 - s))) + 2.25, r2 = 1); }
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
