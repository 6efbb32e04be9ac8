use <sub/other.scad>
module wrapped(h) translate([1, 0, 0]) other(h);
