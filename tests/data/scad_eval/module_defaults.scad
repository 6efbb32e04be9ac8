module peg(h = 5, r = 1, center = false) { cylinder(h = h, r = r, center = center); }
peg(); peg(3); peg(r = 2, h = 7); peg(2, 0.5, true);
