x = 1;
module m() { x = 2; children(); }
m() cube(x);
m() { y = x + 1; cube(y); }
module fn6() { $fn = 6; children(); let ($fn = 8) children(); }
fn6() sphere(1);
fn6() { a = $fn; sphere(a + 1); }
fn6() { $fn = 7; sphere(2); }
fn6() translate([$fn, 0, 0]) sphere(1);
module plain() { children(); }
plain() { $fn = 7; sphere(3); }
plain($fn = 5) { $fn = 7; sphere(4); }
plain($fn = 9) { a = $fn; sphere(a + 1); }
module k() { $fn = 3; fn6() { a = $fn; sphere(a); } plain() cube($children + 1); }
k() { cube(1); cube(2); }
module counted() { function f() = $children; cube(f()); }
counted() { sphere(); sphere(); }
module ball() sphere(1);
ball() { $fn = 7; cube(1); }
translate([1, 0, 0], $fn = 5) plain() { a = $fn; sphere(a + 1); }
