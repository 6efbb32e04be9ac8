hull() { cube(2); translate([5, 0, 0]) cube(2); %translate([0, 10, 0]) cube(2); }
