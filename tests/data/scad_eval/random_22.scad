a = 60;
b = 29.3;
function f(x, y = 2) = x * y + a;
module part(s, t = 270) { for (i1 = [1:2:1]) for (i2 = [-2:2:0]) cube([abs(135) + 1, abs(40.07) + 2.25, 1], center = true); }
translate([(((-90 - b) + 60) * (sin(17.883) - abs(a) + 0.5)), (cos(33) * b), sin(cos((b + -9)))]) for (i1 = [-2:0]) cylinder(h = abs(i1) + 0.5, r1 = abs(i1) + 0.5, r2 = 1);
translate([f(a), f(b, 3), 0]) part(s = b, t = 3);
rotate([sin(cos(46.466179)), abs(sin(360)) + 0.5, 30]) if (a > 0) cube([abs(abs(9) + 0.5) + 0.5, abs(360) + 1, 1], center = false); else hull() { cube([abs(-1.857195) + 0.5, abs(b) + 0.5, 1], center = false); cube([abs(sin(sin(cos(a)))) + 2.25, abs(sin(a)) + 0.5, 1], center = true); }
