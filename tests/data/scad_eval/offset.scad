offset(r = 1) square(2);
offset(delta = 0.5) square(1);
offset(delta = -0.25, chamfer = true, $fn = 8) circle(2);
offset(2) polygon([[0, 0], [3, 0], [0, 3]]);
offset() square(1);
