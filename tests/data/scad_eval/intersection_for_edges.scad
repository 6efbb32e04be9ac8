intersection_for (i = [0:1], j = [0:1]) translate([i, j, 0]) cube(3);
intersection_for (i = []) cube(1);
intersection_for (i = [1]) { cube(i); sphere(2); }
intersection_for (i = [0:1]) echo(i);
intersection_for (i = [0:1], $fn = 4) sphere(i + 1);
module m(n) intersection_for (k = [1:n]) children(k - 1);
m(2) { cube(2); sphere(1.5); }
