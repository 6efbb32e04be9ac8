a = -5;
b = a;
function f(x, y = 2) = x * y + a;
module part(s, t = -17) { if (-19 > 0) cube([abs(-41.32817) + 2.25, abs(t) + 0.5, 1], center = false); else cylinder(h = abs(cos(s)) + 2.25, r1 = abs((abs(sin(t)) + 0.5 - s)) + 1, r2 = 1); }
$fn = 5;
sphere(r = abs((a * abs(abs(b) + 0.5) + 0.5)) + 1);
if (18.7852738 > 0) for (i1 = [1:1]) cube([abs(90) + 0.5, abs(abs(31.8429186) + 0.5) + 0.5, 1], center = true); else for (i1 = [-1:2:1]) hull() { cube([abs(sin((120 + sin(a)))) + 1, abs(cos(((a + 10.95349) * 8))) + 1, 1], center = false); cube([abs((sin(abs(-90) + 0.5) + sin(i1))) + 0.5, abs(cos(abs(sin(270)) + 0.5)) + 2.25, 1], center = false); }
