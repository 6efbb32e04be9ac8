use <use_local_wins.lib/lib.scad>
module thing() cube(1);
function v() = 1;
thing();
other();
sphere(v());
