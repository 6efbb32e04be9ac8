module m() { $fn = 20; sphere(1); n(); }
module n() sphere(2);
m();
sphere(3);
