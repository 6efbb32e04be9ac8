use <use_basic.lib/lib.scad>
k = 100;
part(f(1)) sphere(1);
translate([f(2), 0, 0]) part(k / 50);
