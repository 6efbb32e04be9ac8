module intersection_for() cube(1);
intersection_for();
module minkowski() sphere(1);
minkowski() cube(1);
function cross(a, b) = a + b;
cube(cross([1, 2, 3], [1, 1, 1]));
