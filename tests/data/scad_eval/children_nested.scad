module a() b() children();
module b() translate([1, 0, 0]) children();
a() cube(1);
module c(x) b() { cube(x); children(); }
module d() children(1);
module e(x) d() { cube(x); children(); }
c(2) sphere(1);
e(3) sphere(3);
module rx(t) rotate([t, 0, 0]) children();
rx(10) rx(20) rx(30) cube(1);
module outer() {
  module inner() scale(2) children();
  inner() sphere(1);
  inner() children();
}
outer() cube(0.5);
module twice() { children(); mirror([1, 0, 0]) children(); }
twice() twice() translate([1, 1, 0]) cube(1);
