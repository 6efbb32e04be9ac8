// a plate drawn in a DXF file (an outline with a round hole), extruded
linear_extrude(height = 3) import("plate.dxf", $fn = 24);
