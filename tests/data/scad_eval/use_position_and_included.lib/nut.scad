module nut() cylinder(h = 2, r = 2, $fn = 6);
