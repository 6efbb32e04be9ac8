a = -7;
b = -11;
function f(x, y = 2) = x * y + a;
module part(s, t = -3.36702) { sphere(r = abs((abs((-9 - -11.3108293)) + 0.5 + cos((t + -15)))) + 1); }
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
cube([abs(b) + 0.5, abs(((abs(15.512) + 0.5 + cos(b)) * abs(abs(b) + 0.5) + 0.5)) + 1, 1], center = false);
part(15);
