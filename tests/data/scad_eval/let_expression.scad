a = 5;
x = let (a = a + 1, b = a * 2) [a, b];
cube([x[0], x[1], a]);
function f(t) = let (u = t * 2, v = u + 1) [u, v, let (w = v) w / 2];
translate(f(1.5)) sphere(let (r = 1, s = r + 0.5) s);
y = true ? let (c = 2) c : 3;
z = let (c = 0) c ? 3 : 4;
cube([y, z, let (a = 1) let (b = a + a) (b + a)]);
rotate(let ($fn = 7) [0, 0, $fn]) cylinder(h = let () 2, r = 1);
