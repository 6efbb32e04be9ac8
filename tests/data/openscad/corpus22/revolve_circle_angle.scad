// a C-shaped handle: a revolved circle through 200 degrees, turned and moved
translate([5, 5, 5]) rotate([90, 0, 0]) rotate_extrude(angle = 200, $fn = 96) translate([10, 0]) circle(r = 2, $fn = 96);
