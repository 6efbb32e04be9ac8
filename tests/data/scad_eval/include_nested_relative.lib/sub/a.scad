include <b.scad>
a = 1;
