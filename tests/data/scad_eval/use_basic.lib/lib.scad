k = 3;
function f(x, y = k) = x * y;
module part(s) { cube(s + k); children(); }
sphere(9);
cube(9);
