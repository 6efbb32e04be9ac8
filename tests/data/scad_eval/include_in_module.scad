module m(s) {
  include <include_in_module.lib/body.scad>
}
m(2);
m(s = 3);
