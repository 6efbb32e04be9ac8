a = 135;
b = abs(a) + 0.5;
function f(x, y = 2) = x * y + a;
module part(s, t = -37.4922825) { rotate([-90, abs((-29.8 * cos(s))) + 0.5, abs(s) + 0.5]) translate([abs(s) + 0.5, abs(abs(-90) + 0.5) + 0.5, ((sin(t) * a) + s)]) sphere(r = abs(135) + 1, $fn = 8); }
$fn = 8;
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
part((32.6 * ((b + a) * sin(a))));
