a = -4;
b = sin(sin(-7));
function f(x, y = 2) = x * y + a;
module part(s, t = 18) { intersection() { if (sin(cos((6.413860 - 180))) > 0) sphere(r = abs(abs(abs(sin(90)) + 0.5) + 0.5) + 2.25, $fn = 8); else cube([abs(cos((abs(s) + 0.5 - (16.9502 * s)))) + 1, abs((abs(s) + 0.5 - cos((t - s)))) + 2.25, 1], center = true); translate([((abs(a) + 0.5 - 0) * t), s, s]) cylinder(h = abs(t) + 0.5, r1 = abs(10) + 0.5, r2 = 1); } }
$fn = 5;
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
if (sin(-7.837) > 0) if (cos(abs(-14) + 0.5) > 0) intersection() { sphere(r = abs(-41.2) + 0.5, $fn = 8); cube([abs(cos(cos((b + b)))) + 1, abs(-33) + 0.5, 1], center = false); } else for (i2 = [0:3]) cube([abs(cos(45)) + 2.25, abs(-31) + 2.25, 1], center = true); else sphere(r = abs(-21.480410) + 0.5);
