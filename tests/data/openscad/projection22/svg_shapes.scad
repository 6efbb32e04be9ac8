// an SVG drawing in millimetres with a viewBox: paths with holes, shapes, group transforms
linear_extrude(height = 3) import("svg_shapes.svg");
