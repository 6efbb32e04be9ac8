intersection() { cube(10); %sphere(6); translate([2, 2, 2]) cube(10); }
