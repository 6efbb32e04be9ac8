include <include_basic.lib/parts.scad>
w = 2 * size;
peg(w);
translate([f(3), 0, 0]) cube(size);
