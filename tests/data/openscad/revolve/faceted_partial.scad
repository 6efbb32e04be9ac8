// A partial faceted turn: floor(8 * 200 / 360) = 4 sections.
rotate_extrude(angle = 200, $fn = 8) polygon([[2, 0], [6, 0], [4, 5]]);
