// Three quarters of a torus, raised by 4.
rotate_extrude(angle = 270) translate([8, 4]) circle(r = 2);
