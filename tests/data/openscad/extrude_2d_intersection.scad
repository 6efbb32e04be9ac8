linear_extrude(height = 2, center = true)
    intersection() {
        square(2, center = true);
        circle(r = 1.2);
    }
