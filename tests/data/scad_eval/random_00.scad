a = 25.795440;
b = abs((abs(2) + 0.5 - a)) + 0.5;
function f(x, y = 2) = x * y + a;
module part(s, t = 14) { for (i1 = [0:0.5:0]) rotate(sin(abs((s + s)) + 0.5), [cos(s), 30.33, 1]) sphere(r = abs(abs(abs(abs(a) + 0.5) + 0.5) + 0.5) + 2.25); }
part(17);
