translate([1, 2, 3]);
union();
module nothing() { }
nothing();
cube(1);
