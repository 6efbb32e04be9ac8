a = 16;
b = 10;
function f(x, y = 2) = x * y + a;
module part(s, t = 150) { translate([16.3, abs(((-8 * 270) * abs(13.348) + 0.5)) + 0.5, 45]) rotate([cos(a), abs(s) + 0.5, abs(cos((13 + t))) + 0.5]) cube([abs(abs(t) + 0.5) + 2.25, abs((cos((a - 135)) - abs(sin(s)) + 0.5)) + 2.25, 1], center = false); }
for (i0 = [1:2:1]) for (i1 = [-1:2:-1]) cylinder(h = abs(sin(cos(abs(180) + 0.5))) + 0.5, r1 = abs(a) + 0.5, r2 = 1);
