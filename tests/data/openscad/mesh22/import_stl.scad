// a non-convex bracket read from an STL file, turned and moved
translate([3, -2, 1]) rotate([0, 0, 30]) import("bracket.stl", convexity = 4);
