function sq(x) = x * x;
function hyp(a, b = 4) = sqrt(sq(a) + sq(b));
cube([hyp(3), hyp(5, 12), sq(1.5)]);
