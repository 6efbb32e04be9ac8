r = 0.5;
module other(h) cylinder(h = h, r = r);
function g() = 1;
