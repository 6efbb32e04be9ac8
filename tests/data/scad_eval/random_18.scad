a = -9;
b = a;
function f(x, y = 2) = x * y + a;
module part(s, t = -9) { cylinder(h = abs(cos(s)) + 1, r1 = abs(360) + 2.25, r2 = 1); }
$fn = 8;
if (b > 0) cylinder(h = abs(sin(abs((a + 45)) + 0.5)) + 1, r1 = abs(b) + 1, r2 = 1); else cylinder(h = abs(cos(sin(sin(b)))) + 2.25, r1 = abs(a) + 0.5, r2 = 1);
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
