linear_extrude(height = 2) union() { square(5); *translate([10, 0]) square(5); %circle(r = 20); }
