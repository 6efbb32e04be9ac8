rotate(30) cube(1);
rotate([10, 20, 30]) cube(1);
rotate([45]) cube(1);
rotate([0, 90]) cube(1);
rotate(a = 60, v = [1, 1, 0]) cube(1);
rotate(90, [0, 0, 1]) cube(1);
rotate([]) cube(1);
rotate(a = 33, v = [1, 2]) cube(1);
