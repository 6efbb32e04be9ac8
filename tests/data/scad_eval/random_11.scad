a = 180;
b = abs(12.99) + 0.5;
function f(x, y = 2) = x * y + a;
module part(s, t = -36) { difference() { for (i2 = [-2:-2]) cube([abs(i2) + 1, abs((abs((s - s)) + 0.5 * 12)) + 1, 1], center = true); cylinder(h = abs(abs(((s - -90) + cos(30))) + 0.5) + 1, r1 = abs(120) + 0.5, r2 = 1); } }
cylinder(h = abs(17) + 2.25, r1 = abs(sin(a)) + 0.5, r2 = 1);
