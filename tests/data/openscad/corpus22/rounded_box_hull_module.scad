// a rounded box with a cavity, written with a module and hull of corner cylinders
module rounded_box(size, r, h) {
    hull() for (x = [r, size[0] - r], y = [r, size[1] - r]) translate([x, y, 0]) cylinder(h = h, r = r, $fn = 96);
}
difference() {
    rounded_box([40, 30], 5, 15);
    translate([2, 2, 2]) rounded_box([36, 26], 3, 15);
}
