difference() {
    cube([4, 3, 0.5]);
    for (x = [0.5:1:3.5], y = [0.75, 2.25]) translate([x, y, -1]) cylinder(h = 2, r = 0.3);
}
