difference() { %cube(10); sphere(6); }
