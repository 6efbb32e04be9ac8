{ cube(1); sphere(2); }
{ a = 3; cube(a); }
{ }
{ { translate([a, 0, 0]) cube(1); } }
module m() { { b = 2; cube(b); } { module inner() sphere(b); } inner(); }
m();
translate([1, 0, 0]) { { cylinder(h = 1, r = 1); } c = 4; { sphere(c); } }
{ function f() = 5; }
cube(f());
