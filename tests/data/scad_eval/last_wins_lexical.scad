x = 1;
module m() { y = x + 1; translate([y, 0, 0]) cube(x); }
m();
x2 = x * 10;
sphere(x2);
