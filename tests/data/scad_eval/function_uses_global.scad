k = 2.5;
function f(x) = k * x + 1;
sphere(f(2));
