union() { cube([20, 20, 2]); translate([0, 0, 2]) cube([0.001, 5, 128.4]); }
