// a coloured plate with a coloured hexagonal pocket: polygonal
color("SteelBlue") difference() {
    cube([30, 20, 5]);
    color("orange") translate([15, 10, 2]) cylinder(h = 4, r = 6, $fn = 6);
    for (x = [5, 25]) translate([x, 10, -1]) cylinder(h = 7, r = 1.6, $fn = 8);
}
