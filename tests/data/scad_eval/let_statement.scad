let (a = 2) cube(a);
let (a = 2, b = a * 2) { c = b + 1; translate([a, b, c]) cube([a, b, c]); sphere(1); }
let (a = 1) let (b = a + 2) cube([a, b, 1]);
let ($fn = 5) sphere(1);
module m() sphere(2);
let ($fn = 7) m();
let () cube(3);
let (q = 1);
d = 4;
let (d = d / 2) translate([d, 0, 0]) cube(d);
for (i = [1:2]) let (j = i * 10) translate([j, 0, 0]) cube(i);
if (true) let (k = 3) cube(k);
