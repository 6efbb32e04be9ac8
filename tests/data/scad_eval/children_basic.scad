module all() children();
all() { cube(1); sphere(1); }
module first() children(0);
first() { cube(2); sphere(2); }
module picks() { children([1, 0]); children([0:1]); children([]); children(1.7); children([0:0.5:1]); }
picks() { cube(3); translate([5, 0, 0]) sphere(3); }
module count() cube($children + 1);
count() { cube(1); sphere(1); cylinder(h = 1, r = 1); }
count();
all();
module unused() cube(4);
unused() sphere(4);
module row(d) for (i = [0:$children - 1]) translate([i * d, 0, 0]) children(i);
row(3) { cube(1); sphere(1); cylinder(h = 2, r = 0.5); }
