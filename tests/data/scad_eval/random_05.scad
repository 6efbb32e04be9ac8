a = -90;
b = a;
function f(x, y = 2) = x * y + a;
module part(s, t = 40.1) { hull() { mirror([6, 1, 0]) cube([abs((a + -19)) + 2.25, abs(cos((abs(19) + 0.5 - a))) + 1, 1], center = false); union() { cylinder(h = abs(((cos(s) + (20 - 360)) + cos((135 + a)))) + 1, r1 = abs(t) + 2.25, r2 = 1); cube([abs((t - abs(8) + 0.5)) + 2.25, abs(abs(t) + 0.5) + 1, 1], center = true); } } }
$fn = 8;
part(cos(a));
cube([abs((60 - 10)) + 1, abs(-20) + 1, 1], center = true);
