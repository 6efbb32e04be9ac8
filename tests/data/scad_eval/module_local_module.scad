module outer(n) {
  module inner(k) { translate([k, 0, 0]) sphere(0.4); }
  for (k = [1:n]) inner(k);
}
outer(3);
