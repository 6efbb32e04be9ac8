use <use_children_and_dollar.lib/ops.scad>
spread(3) { sphere(1, $fn = 8); cube(1); }
round_thing($fn = 5);
spread(1) round_thing();
