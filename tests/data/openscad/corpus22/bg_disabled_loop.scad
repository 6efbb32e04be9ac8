// a plate with holes: one hole disabled (*), a background (%) clamp
difference() {
    cube([40, 20, 4]);
    for (x = [5 : 10 : 35]) translate([x, 10, -1]) cylinder(h = 6, r = 2, $fn = 8);
    *translate([20, 10, -1]) cube([10, 10, 10]);
    %translate([0, -5, 0]) cube([40, 5, 10]);
}
