a = 3;
b = ((cos(a) - abs(-18.989) + 0.5) + abs(abs(a) + 0.5) + 0.5);
function f(x, y = 2) = x * y + a;
module part(s, t = 12.6749) { scale([abs(abs(5) + 0.5) + 2.25, abs(abs(5) + 0.5) + 2.25, 1]) cube([abs((abs(t) + 0.5 - a)) + 1, abs((s - cos(t))) + 2.25, 1], center = true); }
$fn = 5;
for (i0 = [-1:1]) mirror([sin(((i0 + b) * 360)), 1, 0]) scale([abs(cos(((6 - 45) - (16 - b)))) + 1, abs(cos(((6 - 45) - (16 - b)))) + 1, 1]) cylinder(h = abs(b) + 2.25, r1 = abs((b - abs(cos(-9)) + 0.5)) + 0.5, r2 = 1);
