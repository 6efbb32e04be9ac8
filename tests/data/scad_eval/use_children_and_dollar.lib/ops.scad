module spread(d) for (i = [0:$children - 1]) translate([i * d, 0, 0]) children(i);
module round_thing() sphere(2);
