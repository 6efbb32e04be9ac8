// A circle centred on the axis, cut to x >= 0 and y >= 0: a hemisphere.
rotate_extrude() intersection() {
  circle(r = 10);
  square(10);
}
