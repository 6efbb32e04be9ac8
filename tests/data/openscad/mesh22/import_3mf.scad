// a notched prism from a 3MF file, scaled
scale([1, 1, 2]) import("notch.3mf");
