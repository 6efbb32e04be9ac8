a = -8.5832;
b = 14;
function f(x, y = 2) = x * y + a;
module part(s, t = 120) { if (cos(60) > 0) rotate([a, cos(((-35.839286 + 135) + abs(2.69178) + 0.5)), a]) cylinder(h = abs(cos(((-6 - 90) - (-27.09389 * 135)))) + 0.5, r1 = abs(abs((cos(180) + (a * t))) + 0.5) + 1, r2 = 1); else sphere(r = abs((47.4394 - abs((s * a)) + 0.5)) + 0.5, $fa = 6); }
$fn = 8;
part(-1);
part(sin(0));
