// a heat sink: thin fins of 0.001 on a base plate
union() {
    cube([20, 5, 2]);
    for (i = [0 : 7]) translate([1 + 2.5 * i, 0, 2]) cube([0.001, 5, 128.4]);
}
