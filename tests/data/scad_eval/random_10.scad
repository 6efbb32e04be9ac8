a = 16;
b = 30;
function f(x, y = 2) = x * y + a;
module part(s, t = 11) { rotate([cos((abs(t) + 0.5 * (30 + t))), (sin(7) + abs(t) + 0.5), abs(sin(3)) + 0.5]) sphere(r = abs(abs(t) + 0.5) + 2.25); }
$fn = 5;
scale([abs(a) + 2.25, abs(a) + 2.25, 1]) hull() { hull() { cube([abs(sin(a)) + 0.5, abs((((b + b) - (19.5069062 - b)) - abs(abs(b) + 0.5) + 0.5)) + 2.25, 1], center = false); cube([abs((abs(b) + 0.5 + 10)) + 1, abs(abs(abs(150) + 0.5) + 0.5) + 0.5, 1], center = true); } if (1.335576 > 0) cube([abs(b) + 2.25, abs(-14) + 2.25, 1], center = false); else cube([abs(abs(b) + 0.5) + 2.25, abs(sin(a)) + 2.25, 1], center = true); }
part(-5);
part(b);
