v = [1, 2, 3, ];
w = [1,,2,, 3];
u = [,];
x = [ ];
cube(v); translate(w) sphere(len(u) + len(x) + 1);
