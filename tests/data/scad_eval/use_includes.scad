use <use_includes.lib/sub/parts.scad>
h = 50;
peg();
translate([0, 0, 9]) peg(2);
