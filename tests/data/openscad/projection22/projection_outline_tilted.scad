// outlines of tilted round solids: a frustum (hull of two ellipses), a cylinder, an ellipsoid
linear_extrude(height = 2) projection() rotate([60, 0, 20]) cylinder(h = 20, r1 = 5, r2 = 2);
translate([30, 0, 0]) linear_extrude(height = 2) projection() rotate([35, 15, 0]) cylinder(h = 15, r = 4, center = true);
translate([0, 30, 0]) linear_extrude(height = 2) projection() rotate([30, 40, 10]) scale([3, 1.5, 1]) sphere(r = 4);
translate([30, 30, 0]) linear_extrude(height = 2) projection() rotate([90, 0, 0]) cylinder(h = 10, r1 = 4, r2 = 0);
