linear_extrude(height = 2) mirror([1, 0]) scale([2, 1]) translate([1, 1]) square(2);
