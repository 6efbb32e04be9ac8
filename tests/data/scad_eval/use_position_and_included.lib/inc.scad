use <nut.scad>
nut_size = 4;
