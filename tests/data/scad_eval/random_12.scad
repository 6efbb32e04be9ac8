a = -23.10050;
b = a;
function f(x, y = 2) = x * y + a;
module part(s, t = 9) { for (i1 = [-1:0.5:1]) cylinder(h = abs(abs((abs(31.569765) + 0.5 * (s * 150))) + 0.5) + 1, r1 = abs(a) + 1, r2 = 1); }
cube([abs((abs(b) + 0.5 + (sin(a) * b))) + 1, abs(sin(((b + b) + 18))) + 0.5, 1], center = true);
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
