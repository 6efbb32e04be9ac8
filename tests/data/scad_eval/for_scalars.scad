for (i = 5) cube(i);
for (i = true) sphere(1);
for (i = undef) cube(3);
for (i = [1:2], j = i * 2) translate([j, 0, 0]) cube(1);
v = [for (i = undef) 1, for (i = 2, j = i + 1) [i, j], for (i = -0.5) i, for (b = false) b ? 1 : 2];
translate([len(v), v[1], v[2]]) cube(v[0][1]);
module ngon(num, r) polygon([for (i = [0:num - 1], a = i * 360 / num) [r * cos(a), r * sin(a)]]);
ngon(3, 10);
translate([20, 0]) ngon(6, 8);
