a = 0;
b = 3;
function f(x, y = 2) = x * y + a;
module part(s, t = 45) { mirror([a, 1, 0]) hull() { sphere(r = abs(a) + 1); cylinder(h = abs((abs(sin(15)) + 0.5 - sin(8))) + 0.5, r1 = abs(s) + 1, r2 = 1); } }
$fn = 8;
part((((a * 8) + (45 + a)) * (-5.675 * (13 - b))));
sphere(r = abs(((abs(b) + 0.5 * (a * b)) - cos(12))) + 0.5, $fn = 8);
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
