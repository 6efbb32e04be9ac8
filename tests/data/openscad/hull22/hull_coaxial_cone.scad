// a cylinder and a cone on one axis: the revolved hull of their ends, frusta
hull() { cylinder(r = 5, h = 2); translate([0, 0, 6]) cylinder(r1 = 2, r2 = 0, h = 3); }
