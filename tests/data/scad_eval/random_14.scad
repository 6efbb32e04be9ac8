a = 120;
b = 8;
function f(x, y = 2) = x * y + a;
module part(s, t = -27.67339) { mirror([45, 1, 0]) mirror([((abs(t) + 0.5 - (180 - a)) - (-47.92048 - a)), 1, 0]) cube([abs((abs((a + 10)) + 0.5 + -11)) + 2.25, abs(abs(a) + 0.5) + 1, 1], center = false); }
$fn = 30;
part(abs(abs(abs(-14.0102741) + 0.5) + 0.5) + 0.5);
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
