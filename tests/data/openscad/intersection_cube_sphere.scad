intersection() {
    cube(2, center = true);
    sphere(r = 1.3);
}
