module a(s) { cube(s); }
module b(s) { translate([s, 0, 0]) a(s / 2); a(s); }
b(4);
