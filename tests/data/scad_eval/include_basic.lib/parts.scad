// parts
size = 1.5;
function f(x) = x * size;
module peg(h) cylinder(h = h, r = size / 3);
sphere(size);