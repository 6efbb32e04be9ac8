use <onpath.scad>
include <both.scad>
onpath();
cube(which);
use <inhome.scad>
inhome();
