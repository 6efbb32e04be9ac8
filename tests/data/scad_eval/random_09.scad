a = 9;
b = abs(18) + 0.5;
function f(x, y = 2) = x * y + a;
module part(s, t = 8) { cylinder(h = abs(45) + 0.5, r1 = abs(abs(s) + 0.5) + 0.5, r2 = 1); }
part(b);
part(abs(abs((a - a)) + 0.5) + 0.5);
if (sin((abs(b) + 0.5 + abs(a) + 0.5)) > 0) for (i1 = [0:2]) cube([abs(b) + 0.5, abs(abs(abs(abs(a) + 0.5) + 0.5) + 0.5) + 1, 1], center = false); else cube([abs(60) + 0.5, abs((cos(cos(0.87242)) + a)) + 2.25, 1], center = true);
