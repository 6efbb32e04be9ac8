x = 1;
module m() cube(x);
module n() { x = 5; m(); }
n();
g = 2;
module p(a = g) sphere(a);
module q() { g = 7; p(); }
q();
function f() = x * 10;
module r() { x = 3; cube(f()); }
r();
for (i = [1:2]) for (i = [i * 10:i * 10 + 1]) translate([i, 0, 0]) cube(1);
