module m() { cube($children); children(0); children(1); children(3); children([1, 3]); children(2); }
m() { echo(1); if (false) cube(2); cube(3); for (i = []) cube(4); }
module n() { children(); }
n() { if (true) cube(1); else sphere(1); let (a = 2) cube(a); for (i = [1:2]) cube(i); }
n();
n() n() n();
