module m(a, b) { cube(a == undef ? 1 : a); }
m(); m(2);
