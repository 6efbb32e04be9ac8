g = 3;
module m(a = g * 2, b = h) { cube([a, b, 1]); }
h = 1.5;
m(); m(b = 2);
module inner() sphere(g);
if (g > 2) { inner(); k = g + 1; translate([k, 0, 0]) inner(); }
function f(x, y = g) = x + y;
cube([f(1), f(y = 2, x = 1), f(x = 0.5)]);
sphere(r = 1, $fn = $fn + 6);
module fnmod() sphere(1, $fn = $fn * 2);
fnmod($fn = 5);
translate([$t, 1e3, .5]) cube(5.);
for (i = [0:0.1:0.3]) translate([i, 0, 0]) cube(0.1);
for (i = [0:0.1:1]) translate([0, i, 0]) cube(0.1);
for (i = [1:1/3:2]) translate([0, 0, i]) cube(0.1);
translate([-0, 0, -0.0]) cube(1);
cube([min([4, 2, 3]), max(1, 7, 3), min(2.5, 9)]);
s = "ab\"c";
if (len(s) == 4 && s != "x" && "abc" < "abd") cube(len(s));
cylinder(h = 1, r1 = 0, r2 = 1);
rotate([0, 0, 0]) cube(1);
rotate(0) cube(1);
rotate([180, 180, 180]) cube(1);
rotate(-90, [0, 1, 0]) cube(1);
rotate(720.5) cube(1);
rotate([1e-7, -30, 1e5]) cube(1);
mirror([0, 0, 0]) cube(1);
scale([1e-3, 2, 3]) cube(1);
