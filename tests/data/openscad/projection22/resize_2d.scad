// 2D resize: a union with an arc on the box, a difference, auto
linear_extrude(height = 2) resize([30, 0], auto = true) union() { square(10); translate([10, 5]) circle(r = 5, $fn = 24); }
translate([0, 30, 0]) linear_extrude(height = 2) resize([0, 8]) difference() { square([10, 5]); translate([5, 2.5]) circle(r = 2, $fn = 16); }
