// a height map cut by a box and a bore
difference() {
    translate([0, 0, 0]) surface(file = "../mesh22/field.dat");
    translate([3, 2, -1]) cylinder(h = 10, r = 1, $fn = 8);
}
