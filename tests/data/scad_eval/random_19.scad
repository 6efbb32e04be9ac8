a = -18;
b = (abs(a) + 0.5 + a);
function f(x, y = 2) = x * y + a;
module part(s, t = 30) { for (i1 = [-2:-2]) scale([abs(i1) + 0.5, abs(i1) + 0.5, 1]) cube([abs(abs(((i1 * -40.8468880) + cos(i1))) + 0.5) + 1, abs(i1) + 1, 1], center = false); }
if ((abs(360) + 0.5 * (b + a)) > 0) cylinder(h = abs((b - abs(13) + 0.5)) + 1, r1 = abs(((sin(a) - b) * sin(sin(21.59)))) + 0.5, r2 = 1); else for (i1 = [-2:0.5:-1]) sphere(r = abs((i1 + sin(i1))) + 1);
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
