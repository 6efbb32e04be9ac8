// % (background) is not part of the model; # (debug) is
%cube(5, center = true);
#sphere(r = 1);
translate([2, 0, 0]) cube(1, center = true);
