a = 135;
b = ((cos(a) * abs(-26.81) + 0.5) * -10);
function f(x, y = 2) = x * y + a;
module part(s, t = -2.725091) { for (i1 = [1:3]) cube([abs(i1) + 2.25, abs(abs((abs(6) + 0.5 - abs(a) + 0.5)) + 0.5) + 2.25, 1], center = true); }
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
