use <use_transitive.lib/lib.scad>
wrapped(2);
