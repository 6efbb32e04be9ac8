include <sizes.scad>
module peg(k = 1) cylinder(h = h * k, r = r);
cube(100);
