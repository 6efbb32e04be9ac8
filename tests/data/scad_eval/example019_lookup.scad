function get_cylinder_h(p) = lookup(p, [[-200, 5], [-50, 20], [-20, 18], [+80, 25], [+150, 2]]);
for (i = [-100:5:+100]) {
  translate([sin(i) * 50, cos(i) * 50, 0]) cylinder(r = 5, h = get_cylinder_h(i) * 3);
}
