// a spiral staircase: a module that calls itself 24 levels deep, each level turned, raised and scaled
module step(n) {
    cube([10, 3, 1]);
    if (n > 0) translate([0, 0, 1]) rotate([0, 0, 15]) scale([0.98, 0.98, 1]) mirror([0, 0, 0]) step(n - 1);
}
step(24);
