// 2D outlines left beside a 3D part (OpenSCAD ignores them with a warning)
union() {
    for (i = [0 : 2]) translate([10 * i, 0, 0]) cylinder(h = 4, r = 3, $fn = 96);
    square([30, 2]);
}
circle(r = 8);
