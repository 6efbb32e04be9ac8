include <include_nested_relative.lib/sub/a.scad>
cube(b);
include <include_nested_relative.lib/b.scad>
sphere(c);
