use <use_twice.lib/lib.scad>
use <use_twice.lib/lib.scad>
part();
