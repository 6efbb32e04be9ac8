a = -12;
b = ((sin(a) - sin(a)) * abs(abs(a) + 0.5) + 0.5);
function f(x, y = 2) = x * y + a;
module part(s, t = 30) { cylinder(h = abs(sin((-90 * abs(12) + 0.5))) + 1, r1 = abs(abs((11 * (a + 8.4))) + 0.5) + 0.5, r2 = 1); }
$fn = 5;
part((a * abs(abs(a) + 0.5) + 0.5));
part(a);
