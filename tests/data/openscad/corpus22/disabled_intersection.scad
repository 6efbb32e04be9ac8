intersection() { cube(8, center = true); *cube(1); sphere(5); }
