a = 30;
b = a;
function f(x, y = 2) = x * y + a;
module part(s, t = -12) { cube([abs((a - ((s + 12.09915) * 60))) + 1, abs(((sin(13) - a) - abs(t) + 0.5)) + 2.25, 1], center = false); }
$fn = 12;
part((cos(a) * (sin(-20) * sin(a))));
for (i0 = [-2:1]) for (i1 = [0:0.5:0]) for (i2 = [-1:-1]) sphere(r = abs(a) + 0.5);
