a = -8.200635;
b = (12 - abs((150 - a)) + 0.5);
function f(x, y = 2) = x * y + a;
module part(s, t = -13) { for (i1 = [-2:-2]) mirror([cos((t + sin(45))), 1, 0]) cylinder(h = abs(cos((abs(a) + 0.5 + sin(s)))) + 1, r1 = abs((cos(t) + t)) + 0.5, r2 = 1); }
cube([abs(b) + 2.25, abs(abs((abs(b) + 0.5 + sin(29))) + 0.5) + 0.5, 1], center = false);
