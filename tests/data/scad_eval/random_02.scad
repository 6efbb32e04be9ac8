a = 60;
b = abs(abs(a) + 0.5) + 0.5;
function f(x, y = 2) = x * y + a;
module part(s, t = 18.124618) { if (abs(((37.10330 - -10) + a)) + 0.5 > 0) mirror([sin(abs((28.97476 + a)) + 0.5), 1, 0]) cube([abs(135) + 2.25, abs(sin(t)) + 1, 1], center = true); else cube([abs(sin(abs(t) + 0.5)) + 0.5, abs((cos(a) + s)) + 0.5, 1], center = true); }
scale([abs(sin(sin(cos(-20.9247154)))) + 1, abs(sin(sin(cos(-20.9247154)))) + 1, 1]) scale([abs((abs(sin(150)) + 0.5 + ((10 * 5) - (-9 * a)))) + 0.5, abs((abs(sin(150)) + 0.5 + ((10 * 5) - (-9 * a)))) + 0.5, 1]) mirror([sin(30), 1, 0]) cube([abs(-13.354032) + 0.5, abs(abs(18.9628) + 0.5) + 1, 1], center = false);
