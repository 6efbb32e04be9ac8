translate([1, 0, 0]) { a = 2; cube(a); rotate(45) { b = a * 2; sphere(b); } }
