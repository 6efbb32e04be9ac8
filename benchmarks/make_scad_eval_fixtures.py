# ruff: noqa: E501 (the programs are written one per line)
"""Writes tests/data/scad_eval/: small .scad programs of the subset read in-process
(isocsg.openscad.evaluate) and the openscad program's .csg export of each, which
tests/test_openscad_evaluate.py compares with the evaluator's tree.

    PYTHONPATH=$PWD python benchmarks/make_scad_eval_fixtures.py   (needs openscad 2021.01)
"""

from __future__ import annotations

import os
import random
from pathlib import Path

from isocsg.openscad.program import scad_to_csg

OUT = Path(__file__).resolve().parent.parent / "tests" / "data" / "scad_eval"

HAND = {
    "variables": "a = 2; b = a * 3 + 1; c = [a, b, -a / 4];\ntranslate(c) cube([a, b, 0.5]);\n",
    "last_wins_lexical": "x = 1;\nmodule m() { y = x + 1; translate([y, 0, 0]) cube(x); }\nm();\nx2 = x * 10;\nsphere(x2);\n",
    "for_range": "for (i = [0:3]) translate([i * 2, 0, 0]) cube(1);\n",
    "for_step": "for (i = [0:0.1:1]) translate([i, i * i, 0]) sphere(0.05, $fn = 6);\n",
    "for_negative_step": "for (i = [5:-1.5:0]) translate([0, 0, i]) cylinder(h = 1, r = i + 1);\n",
    "for_list": "for (p = [[1, 2, 3], [-1, 0, 2.5], [0, 0, 0]]) translate(p) cube(0.5, center = true);\n",
    "for_two_variables": "for (i = [0:2], j = [0:1]) translate([i, j, 0]) cube(0.5);\n",
    "for_empty": "for (i = []) cube(1);\ncube(2);\n",
    "if_else": "big = true;\nif (big) cube(3); else sphere(1);\nif (!big) cube(1);\nif (1 > 2) sphere(2); else if (2 > 1) cylinder(h = 2, r = 1);\n",
    "ternary_logic": "a = 3; b = a > 2 && a < 5 ? 10 : 20; c = (a == 3 || false) ? [1, 2] : [3, 4];\ncube([b, c[0], c[1]]);\n",
    "module_defaults": "module peg(h = 5, r = 1, center = false) { cylinder(h = h, r = r, center = center); }\npeg(); peg(3); peg(r = 2, h = 7); peg(2, 0.5, true);\n",
    "module_nested": "module a(s) { cube(s); }\nmodule b(s) { translate([s, 0, 0]) a(s / 2); a(s); }\nb(4);\n",
    "module_local_module": "module outer(n) {\n  module inner(k) { translate([k, 0, 0]) sphere(0.4); }\n  for (k = [1:n]) inner(k);\n}\nouter(3);\n",
    "functions": "function sq(x) = x * x;\nfunction hyp(a, b = 4) = sqrt(sq(a) + sq(b));\ncube([hyp(3), hyp(5, 12), sq(1.5)]);\n",
    "function_uses_global": "k = 2.5;\nfunction f(x) = k * x + 1;\nsphere(f(2));\n",
    "trig_special": "for (a = [0:15:360]) translate([cos(a) * 10, sin(a) * 10, tan(a == 90 || a == 270 ? 0 : a)]) cube(1);\n",
    "trig_generic": "for (a = [7.3, 123.4, -45.6, 1000.1]) rotate(a) translate([cos(a), sin(a), 0]) cube([1, 2, 3]);\n",
    "inverse_trig": "cube([asin(0.5) / 10, acos(0.5) / 10, atan(1) / 10]);\ntranslate([atan2(1, 1), atan2(-1, 2), 0]) sphere(1);\n",
    "math_builtins": "cube([abs(-2), sign(-3) + 2, sqrt(2)]);\ntranslate([pow(2, 3), exp(1), ln(10)]) cube([log(100), log(2, 8), floor(2.7) + ceil(0.2)]);\ntranslate([round(2.5), round(-2.5), min(3, 1, 2)]) cube([max([1, 5, 2]), norm([3, 4]), len([1, 2, 3])]);\n",
    "concat_index": "v = concat([1, 2], [3], 4);\nw = [[1, 2], [3, 4]];\ncube([v[3], w[1][0], v.z]);\n",
    "vector_ops": "a = [1, 2, 3]; b = [0.5, -1, 2];\ntranslate(a + b) cube(a * 2);\ntranslate(a - b) cube(b * -1 + [2, 3, 0] / 2 + [1, 1, 1]);\ntranslate(3 * a) sphere(2);\n",
    "modulo_power": "for (i = [0:7]) translate([i % 3, 2 ^ (i % 4), -i ^ 2 / 10]) cube(0.5);\n",
    "fn_global": "$fn = 12;\nsphere(2); cylinder(h = 3, r = 1); translate([5, 0, 0]) circle(1);\n",
    "fn_fa_fs_arguments": "sphere(2, $fn = 7); sphere(r = 1, $fa = 5, $fs = 0.5);\ncylinder(h = 1, r1 = 2, r2 = 0, $fn = 4);\n",
    "fn_dynamic": "module ball(r) sphere(r);\nball(2, $fn = 9);\ntranslate([4, 0, 0]) ball(1);\nunion($fn = 5) { sphere(1); cylinder(h = 2, r = 0.5); }\n",
    "fn_in_module": "module m() { $fn = 20; sphere(1); n(); }\nmodule n() sphere(2);\nm();\nsphere(3);\n",
    "fn_builtin_arguments": "translate([1, 0, 0], $fn = 5) sphere(1); color([1, 0, 0], $fn = 6) sphere(1);\nhull($fn = 7) sphere(1); union($fn = 8) sphere(1); difference($fn = 9) sphere(1);\nrotate(5, $fn = 11) sphere(1); linear_extrude(1, $fn = 12) circle(1);\n",
    "cylinder_forms": "cylinder(2, 1, 3); cylinder(3, 2); cylinder(h = 2, d = 4); cylinder(h = 2, d1 = 4, d2 = 2, center = true);\ncylinder(r = 1); cylinder(1, r1 = 0.5, r2 = 1.5);\n",
    "sphere_circle_d": "sphere(d = 5); circle(d = 3); sphere(); circle();\n",
    "cube_square_forms": "cube(); cube(2); cube([1, 2, 3], true); cube(size = 4, center = false);\nsquare(); square(2); square([1, 3], center = true);\n",
    "rotate_forms": "rotate(30) cube(1);\nrotate([10, 20, 30]) cube(1);\nrotate([45]) cube(1);\nrotate([0, 90]) cube(1);\nrotate(a = 60, v = [1, 1, 0]) cube(1);\nrotate(90, [0, 0, 1]) cube(1);\nrotate([]) cube(1);\nrotate(a = 33, v = [1, 2]) cube(1);\n",
    "mirror_scale": "mirror([1, 0, 0]) cube(1);\nmirror([1, 1, 0]) cube(1);\nmirror([0, 1]) cube(1);\nscale(2) cube(1);\nscale([1, 2, 3]) sphere(1);\nscale([2, 0.5]) cube(1);\n",
    "multmatrix": "multmatrix([[1, 0.5, 0, 1], [0, 1, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]]) cube(1);\nmultmatrix([[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]) sphere(1);\n",
    "translate_2d": "translate([1, 2]) cube(1);\ntranslate([0.1, 0.2, 0.3]) translate([-1, 0, 0]) sphere(1);\n",
    "color_vectors": "color([1, 0, 0]) cube(1);\ncolor([0.2, 0.4, 0.6, 0.8]) sphere(1);\ncolor([0.1, 0.3, 0.7], 0.5) cylinder(h = 1, r = 1);\ncolor(c = [0.33, 0.66, 0.99]) cube(2);\n",
    "booleans": "difference() { cube(10, center = true); sphere(6); for (a = [0:90:270]) rotate([0, 0, a]) translate([5, 0, 0]) cylinder(h = 20, r = 1, center = true); }\nintersection() { cube(4); sphere(5); }\nhull() { cube(1); translate([3, 3, 3]) sphere(1); }\nunion() { cube(1); }\n",
    "polyhedron": "pts = [[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10]];\npolyhedron(points = pts, faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);\npolyhedron(pts, [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]], 3);\n",
    "polygon_extrude": "linear_extrude(height = 3) polygon([[0, 0], [4, 0], [2, 3]]);\nlinear_extrude(5, center = true, twist = 90, slices = 8) square(2, center = true);\nlinear_extrude(height = 2, scale = [2, 0.5], $fn = 16) circle(1);\nlinear_extrude(height = 1, scale = 0.5) polygon(points = [[0, 0], [3, 0], [3, 3], [0, 3], [1, 1], [2, 1], [2, 2], [1, 2]], paths = [[0, 1, 2, 3], [4, 5, 6, 7]]);\n",
    "rounding_ties": "cube([100.0625, 6.109375, 0.765625]); sphere(100.0625); translate([100.0625, 6.109375, 1]) cube(1);\npolyhedron([[100.0625, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]);\nlinear_extrude(height = 100.0625, twist = 6.109375, scale = 100.0625) square(1);\ncolor([0.5, 0.5, 0.5], 0.765625) cube(1);\noffset(r = 100.0625) square(1);\nfor (i = [0:7]) translate([i / 16 + 0.03125, 1234565, -2.5e-5 * i]) cube(i / 32 + 1.0000005);\n",
    "semantics_mix": 'g = 3;\nmodule m(a = g * 2, b = h) { cube([a, b, 1]); }\nh = 1.5;\nm(); m(b = 2);\nmodule inner() sphere(g);\nif (g > 2) { inner(); k = g + 1; translate([k, 0, 0]) inner(); }\nfunction f(x, y = g) = x + y;\ncube([f(1), f(y = 2, x = 1), f(x = 0.5)]);\nsphere(r = 1, $fn = $fn + 6);\nmodule fnmod() sphere(1, $fn = $fn * 2);\nfnmod($fn = 5);\ntranslate([$t, 1e3, .5]) cube(5.);\nfor (i = [0:0.1:0.3]) translate([i, 0, 0]) cube(0.1);\nfor (i = [0:0.1:1]) translate([0, i, 0]) cube(0.1);\nfor (i = [1:1/3:2]) translate([0, 0, i]) cube(0.1);\ntranslate([-0, 0, -0.0]) cube(1);\ncube([min([4, 2, 3]), max(1, 7, 3), min(2.5, 9)]);\ns = "ab\\"c";\nif (len(s) == 4 && s != "x" && "abc" < "abd") cube(len(s));\ncylinder(h = 1, r1 = 0, r2 = 1);\nrotate([0, 0, 0]) cube(1);\nrotate(0) cube(1);\nrotate([180, 180, 180]) cube(1);\nrotate(-90, [0, 1, 0]) cube(1);\nrotate(720.5) cube(1);\nrotate([1e-7, -30, 1e5]) cube(1);\nmirror([0, 0, 0]) cube(1);\nscale([1e-3, 2, 3]) cube(1);\n',
    "lexical_scoping": 'x = 1;\nmodule m() cube(x);\nmodule n() { x = 5; m(); }\nn();\ng = 2;\nmodule p(a = g) sphere(a);\nmodule q() { g = 7; p(); }\nq();\nfunction f() = x * 10;\nmodule r() { x = 3; cube(f()); }\nr();\nfor (i = [1:2]) for (i = [i * 10:i * 10 + 1]) translate([i, 0, 0]) cube(1);\n',
    "vector_commas": "v = [1, 2, 3, ];\nw = [1,,2,, 3];\nu = [,];\nx = [ ];\ncube(v); translate(w) sphere(len(u) + len(x) + 1);\n",
    "offset": "offset(r = 1) square(2);\noffset(delta = 0.5) square(1);\noffset(delta = -0.25, chamfer = true, $fn = 8) circle(2);\noffset(2) polygon([[0, 0], [3, 0], [0, 3]]);\noffset() square(1);\n",
    "rotate_extrude": "rotate_extrude($fn = 24) translate([5, 0]) circle(1);\nrotate_extrude(angle = 90, convexity = 4) translate([3, 0]) square([1, 2]);\nrotate_extrude(angle = 400) translate([2, 0]) circle(0.5);\n",
    "echo_dropped": "a = 4;\necho(\"a is\", a);\necho(version=version());\nmodule e() { echo(\"inside\"); cube(a); }\ne();\n",
    "nested_blocks": "translate([1, 0, 0]) { a = 2; cube(a); rotate(45) { b = a * 2; sphere(b); } }\n",
    "empty_children": "translate([1, 2, 3]);\nunion();\nmodule nothing() { }\nnothing();\ncube(1);\n",
    "long_numbers": "translate([1 / 3, 2 / 3, 0.1 + 0.2]) cube([1e-7 + 1, 123456.789, 0.000123456789]);\nsphere(PI);\n",
    "lookup": "t = [[-1, 2], [0.5, 3.25], [4, -1], [2, 7]];\nfor (k = [-3, -1, 0, 0.3, 0.5, 1.7, 2, 3.9, 4, 6]) translate([k, lookup(k, t), 0]) cube(0.5);\ncube([lookup(1, [[1, 4]]), lookup(5, [[0, 1], [10, 3]]), lookup(2.5, [[3, 1], [2, 5], [3, 9]])]);\n",
    "example019_lookup": "function get_cylinder_h(p) = lookup(p, [[-200, 5], [-50, 20], [-20, 18], [+80, 25], [+150, 2]]);\nfor (i = [-100:5:+100]) {\n  translate([sin(i) * 50, cos(i) * 50, 0]) cylinder(r = 5, h = get_cylinder_h(i) * 3);\n}\n",
    "undef_default": "module m(a, b) { cube(a == undef ? 1 : a); }\nm(); m(2);\n",
    "strings": "name = \"part\";\nif (name == \"part\") cube(1); else sphere(1);\nif (len(name) > 3) translate([2, 0, 0]) cube(len(name));\n",
    "let_expression": "a = 5;\nx = let (a = a + 1, b = a * 2) [a, b];\ncube([x[0], x[1], a]);\nfunction f(t) = let (u = t * 2, v = u + 1) [u, v, let (w = v) w / 2];\ntranslate(f(1.5)) sphere(let (r = 1, s = r + 0.5) s);\ny = true ? let (c = 2) c : 3;\nz = let (c = 0) c ? 3 : 4;\ncube([y, z, let (a = 1) let (b = a + a) (b + a)]);\nrotate(let ($fn = 7) [0, 0, $fn]) cylinder(h = let () 2, r = 1);\n",
    "let_statement": "let (a = 2) cube(a);\nlet (a = 2, b = a * 2) { c = b + 1; translate([a, b, c]) cube([a, b, c]); sphere(1); }\nlet (a = 1) let (b = a + 2) cube([a, b, 1]);\nlet ($fn = 5) sphere(1);\nmodule m() sphere(2);\nlet ($fn = 7) m();\nlet () cube(3);\nlet (q = 1);\nd = 4;\nlet (d = d / 2) translate([d, 0, 0]) cube(d);\nfor (i = [1:2]) let (j = i * 10) translate([j, 0, 0]) cube(i);\nif (true) let (k = 3) cube(k);\n",
    "comprehension_for": "v = [for (i = [0:3]) i * 2];\ncube([v[1], v[2], v[3]]);\npolygon([for (i = [0:2], j = [0:i]) [i, j + 0.5 * i]]);\nn = 5;\ntranslate([10, 0, 0]) polygon([for (k = [0:n - 1]) [cos(360 * k / n), sin(360 * k / n)]]);\nfor (p = [for (q = [[1, 2, 3], [4, 5, 6]]) q / 2]) translate(p) cube(1);\nm = [for (i = [0:2]) [for (j = [0:3]) i == j ? 1 : j / 10]];\nmultmatrix(m) cube(1);\nw = [for (i = [0:0.25:1]) i * i, for (x = []) x, for (i = [3:-1:1]) -i];\ntranslate([w[1], w[5], w[7]]) cube(len(w));\npairs = [for (i = [0:1]) for (j = [0:1]) [i, j]];\ntranslate([len(pairs), pairs[3][0], pairs[2][1]]) sphere(1);\n",
    "comprehension_if_each": "v = [for (i = [0:5]) if (i % 2 == 0) i + 1];\ncube(v);\npolygon([for (i = [0:4]) if (i < 2) [i, i * i] else if (i < 4) [-i, 2] else [0, -3]]);\nd = [for (a = [0:1]) if (a == 0) if (false) 1 else 2];\ne = concat([if (true) 1], [if (false) 1], [if (false) 1 else each [2, 3]]);\ntranslate([d[0], len(d), 0]) cube(e);\nf = [each [1, 2], each [0:2], 5, each 5, each true ? 1 : 0, each [[7, 8]]];\ncube([len(f), f[6], f[8][1]]);\ng = [each for (i = [0:1]) [i + 1, i + 2]];\nh = [for (i = [0:2]) each [i, -i]];\nk = [each each [[1, 2], [3]]];\ntranslate([g[3], h[5], len(k)]) cube([len(g), len(h), k[2]]);\n",
    "comprehension_let_c_for": "v = [let (a = 1) for (i = [0:a]) i + 1, for (i = [0:3]) let (a = i * 2) if (a > 2) a, 1, for (i = [0:1]) i + 3];\ncube([len(v), v[2], v[5]]);\npolygon([for (i = 0, j = 0; i < 3; i = i + 1, j = i) [i, j * j + 1]]);\nw = [for (x = 1; x < 100; x = x * 3) x];\ntranslate([len(w), w[3], 0]) cube(1);\nz = [for (i = 10; i < 3; i = i + 1) i];\ncube(len(z) + 1);\nfunction pts(n, r) = [for (i = [0:n - 1]) let (a = 360 * i / n) [r * cos(a), r * sin(a)]];\nlinear_extrude(2) polygon(pts(6, 3));\nu = [for (i = [0:2]) let (b = i, c = b * b) [b, c, let (e = c + 1) e]];\ntranslate(u[2]) cube(u[1] + [1, 1, 1]);\n",
    "comprehension_polyhedron": "function ring(z, r, n) = [for (i = [0:n - 1]) [r * cos(360 * i / n), r * sin(360 * i / n), z]];\nn = 6;\npts = [each ring(0, 2, n), each ring(3, 1, n)];\nfaces = [[for (i = [n - 1:-1:0]) i], [for (i = [n:2 * n - 1]) i], for (i = [0:n - 1]) [i, (i + 1) % n, n + (i + 1) % n, n + i]];\npolyhedron(points = pts, faces = faces);\n",
    "children_basic": "module all() children();\nall() { cube(1); sphere(1); }\nmodule first() children(0);\nfirst() { cube(2); sphere(2); }\nmodule picks() { children([1, 0]); children([0:1]); children([]); children(1.7); children([0:0.5:1]); }\npicks() { cube(3); translate([5, 0, 0]) sphere(3); }\nmodule count() cube($children + 1);\ncount() { cube(1); sphere(1); cylinder(h = 1, r = 1); }\ncount();\nall();\nmodule unused() cube(4);\nunused() sphere(4);\nmodule row(d) for (i = [0:$children - 1]) translate([i * d, 0, 0]) children(i);\nrow(3) { cube(1); sphere(1); cylinder(h = 2, r = 0.5); }\n",
    "children_nested": "module a() b() children();\nmodule b() translate([1, 0, 0]) children();\na() cube(1);\nmodule c(x) b() { cube(x); children(); }\nmodule d() children(1);\nmodule e(x) d() { cube(x); children(); }\nc(2) sphere(1);\ne(3) sphere(3);\nmodule rx(t) rotate([t, 0, 0]) children();\nrx(10) rx(20) rx(30) cube(1);\nmodule outer() {\n  module inner() scale(2) children();\n  inner() sphere(1);\n  inner() children();\n}\nouter() cube(0.5);\nmodule twice() { children(); mirror([1, 0, 0]) children(); }\ntwice() twice() translate([1, 1, 0]) cube(1);\n",
    "children_scoping": "x = 1;\nmodule m() { x = 2; children(); }\nm() cube(x);\nm() { y = x + 1; cube(y); }\nmodule fn6() { $fn = 6; children(); let ($fn = 8) children(); }\nfn6() sphere(1);\nfn6() { a = $fn; sphere(a + 1); }\nfn6() { $fn = 7; sphere(2); }\nfn6() translate([$fn, 0, 0]) sphere(1);\nmodule plain() { children(); }\nplain() { $fn = 7; sphere(3); }\nplain($fn = 5) { $fn = 7; sphere(4); }\nplain($fn = 9) { a = $fn; sphere(a + 1); }\nmodule k() { $fn = 3; fn6() { a = $fn; sphere(a); } plain() cube($children + 1); }\nk() { cube(1); cube(2); }\nmodule counted() { function f() = $children; cube(f()); }\ncounted() { sphere(); sphere(); }\nmodule ball() sphere(1);\nball() { $fn = 7; cube(1); }\ntranslate([1, 0, 0], $fn = 5) plain() { a = $fn; sphere(a + 1); }\n",
    "children_skipped": "module m() { cube($children); children(0); children(1); children(3); children([1, 3]); children(2); }\nm() { echo(1); if (false) cube(2); cube(3); for (i = []) cube(4); }\nmodule n() { children(); }\nn() { if (true) cube(1); else sphere(1); let (a = 2) cube(a); for (i = [1:2]) cube(i); }\nn();\nn() n() n();\n",
    "for_scalars": "for (i = 5) cube(i);\nfor (i = true) sphere(1);\nfor (i = undef) cube(3);\nfor (i = [1:2], j = i * 2) translate([j, 0, 0]) cube(1);\nv = [for (i = undef) 1, for (i = 2, j = i + 1) [i, j], for (i = -0.5) i, for (b = false) b ? 1 : 2];\ntranslate([len(v), v[1], v[2]]) cube(v[0][1]);\nmodule ngon(num, r) polygon([for (i = [0:num - 1], a = i * 360 / num) [r * cos(a), r * sin(a)]]);\nngon(3, 10);\ntranslate([20, 0]) ngon(6, 8);\n",
    "range_variable": "r = [1:3];\nfor (i = r) translate([i, 0, 0]) cube(0.5);\nfor (i = [0:2:9]) translate([0, i, 0]) cube(0.5);\n",
    "cross_products": "a = cross([1, 2, 3], [4, 5, 6]);\nb = cross([0.1, -2.5, 3e3], [7, 0.3, -1]);\nc = cross([1, 0, 0], [0, 1, 0]);\nd = cross([2, 3], [5, -7]);\ntranslate(a) cube(c + [1, 1, 0]);\ntranslate(b / 1000) sphere(abs(d) / 10);\n",
    "minkowski_args": "minkowski() { cube(1); sphere(1); }\nminkowski(3) { cube([2, 1, 1]); cylinder(h = 1, r = 0.5); }\nminkowski(convexity = 2.7) cube(1);\nminkowski($fn = 5) { cube(1); sphere(1); }\nminkowski();\n",
    "minkowski_nested": "module rounded(r) minkowski() { children(); sphere(r, $fn = 8); }\nrounded(0.5) cube([3, 2, 1]);\ntranslate([5, 0, 0]) minkowski() { minkowski() { cube(1); cube(2); } for (i = [0:1]) sphere(i + 1); }\n",
    "intersection_for_basic": "intersection_for (i = [0:2]) rotate(i * 30) cube(5, center = true);\nintersection_for (a = [[1, 2, 3], [2, 1, 3]]) cube(a);\n",
    "intersection_for_edges": "intersection_for (i = [0:1], j = [0:1]) translate([i, j, 0]) cube(3);\nintersection_for (i = []) cube(1);\nintersection_for (i = [1]) { cube(i); sphere(2); }\nintersection_for (i = [0:1]) echo(i);\nintersection_for (i = [0:1], $fn = 4) sphere(i + 1);\nmodule m(n) intersection_for (k = [1:n]) children(k - 1);\nm(2) { cube(2); sphere(1.5); }\n",
    "builtins_shadowed": "module intersection_for() cube(1);\nintersection_for();\nmodule minkowski() sphere(1);\nminkowski() cube(1);\nfunction cross(a, b) = a + b;\ncube(cross([1, 2, 3], [1, 1, 1]));\n",
    "bare_blocks": "{ cube(1); sphere(2); }\n{ a = 3; cube(a); }\n{ }\n{ { translate([a, 0, 0]) cube(1); } }\nmodule m() { { b = 2; cube(b); } { module inner() sphere(b); } inner(); }\nm();\ntranslate([1, 0, 0]) { { cylinder(h = 1, r = 1); } c = 4; { sphere(c); } }\n{ function f() = 5; }\ncube(f());\n",
}

OPS = ["+", "-", "*"]

#: Programs with library files: NAME.scad names NAME.lib/<path>; NAME.lib/openscadpath/ and
#: NAME.lib/home/ (when given) are OPENSCADPATH and HOME for the export (see :func:`fixture_env`).
FILES: dict[str, tuple[str, dict[str, str]]] = {
    "include_basic": ("include <include_basic.lib/parts.scad>\nw = 2 * size;\npeg(w);\ntranslate([f(3), 0, 0]) cube(size);\n",
                      {"parts.scad": "// parts\nsize = 1.5;\nfunction f(x) = x * size;\nmodule peg(h) cylinder(h = h, r = size / 3);\nsphere(size);"}),
    "include_nested_relative": ("include <include_nested_relative.lib/sub/a.scad>\ncube(b);\ninclude <include_nested_relative.lib/b.scad>\nsphere(c);\n",
                                {"sub/a.scad": "include <b.scad>\na = 1;\n", "sub/b.scad": "b = 2; translate([b, 0, 0]) cube(1);\n",
                                 "b.scad": "c = 3;\n"}),
    "include_in_module": ("module m(s) {\n  include <include_in_module.lib/body.scad>\n}\nm(2);\nm(s = 3);\n",
                          {"body.scad": "k = s * 2;\ntranslate([k, 0, 0]) cube(s);\n"}),
    "use_basic": ("use <use_basic.lib/lib.scad>\nk = 100;\npart(f(1)) sphere(1);\ntranslate([f(2), 0, 0]) part(k / 50);\n",
                  {"lib.scad": "k = 3;\nfunction f(x, y = k) = x * y;\nmodule part(s) { cube(s + k); children(); }\nsphere(9);\ncube(9);\n"}),
    "use_transitive": ("use <use_transitive.lib/lib.scad>\nwrapped(2);\n",
                       {"lib.scad": "use <sub/other.scad>\nmodule wrapped(h) translate([1, 0, 0]) other(h);\n",
                        "sub/other.scad": "r = 0.5;\nmodule other(h) cylinder(h = h, r = r);\nfunction g() = 1;\n"}),
    "use_position_and_included": ("$fn = 7;\nbolt(3);\ninclude <use_position_and_included.lib/inc.scad>\nnut();\nuse <use_position_and_included.lib/bolt.scad>\n",
                                  {"inc.scad": "use <nut.scad>\nnut_size = 4;\n",
                                   "nut.scad": "module nut() cylinder(h = 2, r = 2, $fn = 6);\n",
                                   "bolt.scad": "module bolt(l) { sphere(1); cylinder(h = l, r = 0.5); }\n"}),
    "use_children_and_dollar": ("use <use_children_and_dollar.lib/ops.scad>\nspread(3) { sphere(1, $fn = 8); cube(1); }\nround_thing($fn = 5);\nspread(1) round_thing();\n",
                                {"ops.scad": "module spread(d) for (i = [0:$children - 1]) translate([i * d, 0, 0]) children(i);\n"
                                             "module round_thing() sphere(2);\n"}),
    "use_local_wins": ("use <use_local_wins.lib/lib.scad>\nmodule thing() cube(1);\nfunction v() = 1;\nthing();\nother();\nsphere(v());\n",
                       {"lib.scad": "module thing() sphere(5);\nmodule other() thing();\nfunction v() = 5;\n"}),
    "use_includes": ("use <use_includes.lib/sub/parts.scad>\nh = 50;\npeg();\ntranslate([0, 0, 9]) peg(2);\n",
                     {"sub/parts.scad": "include <sizes.scad>\nmodule peg(k = 1) cylinder(h = h * k, r = r);\ncube(100);\n",
                      "sub/sizes.scad": "h = 4;\nr = h / 8;\n", "sizes.scad": "h = 1000;\nr = 1000;\n"}),
    "use_twice": ("use <use_twice.lib/lib.scad>\nuse <use_twice.lib/lib.scad>\npart();\n",
                  {"lib.scad": "module part() cube(2);\n"}),
    "library_path_order": ("use <onpath.scad>\ninclude <both.scad>\nonpath();\ncube(which);\nuse <inhome.scad>\ninhome();\n",
                           {"openscadpath/onpath.scad": "module onpath() cube(11);\n", "openscadpath/both.scad": "which = 2;\n",
                            "home/.local/share/OpenSCAD/libraries/both.scad": "which = 3;\n",
                            "home/.local/share/OpenSCAD/libraries/inhome.scad": "module inhome() cube(13);\n",
                            "home/.local/share/OpenSCAD/libraries/onpath.scad": "module onpath() cube(12);\n"}),
    "library_home": ("use <inhome.scad>\ninhome();\n",
                     {"home/.local/share/OpenSCAD/libraries/inhome.scad": "module inhome() cube(13);\n"}),
}


def fixture_env(lib: Path) -> dict[str, str]:
    """OPENSCADPATH and HOME for a fixture's export and evaluation: its folders when it has them."""
    env = {"OPENSCADPATH": str(lib / "openscadpath") if (lib / "openscadpath").is_dir() else ""}
    if (lib / "home").is_dir():
        env["HOME"] = str(lib / "home")
    return env


def _num(rng: random.Random) -> str:
    return rng.choice([str(rng.randint(-20, 20)), f"{rng.uniform(-50, 50):.{rng.randint(0, 7)}f}",
                       str(rng.choice([30, 45, 60, 90, 120, 135, 150, 180, 270, 360, -90]))])


def _expr(rng: random.Random, names: list[str], depth: int = 0) -> str:
    r = rng.random()
    if depth > 2 or r < 0.35:
        return rng.choice(names) if names and rng.random() < 0.5 else _num(rng)
    if r < 0.6:
        return f"({_expr(rng, names, depth + 1)} {rng.choice(OPS)} {_expr(rng, names, depth + 1)})"
    if r < 0.8:
        return f"{rng.choice(['sin', 'cos'])}({_expr(rng, names, depth + 1)})"
    return f"abs({_expr(rng, names, depth + 1)}) + 0.5"


def _positive(rng: random.Random, names: list[str]) -> str:
    return f"abs({_expr(rng, names)}) + {rng.choice(['0.5', '1', '2.25'])}"


def _shape(rng: random.Random, names: list[str], depth: int) -> str:
    r = rng.random()
    if depth > 2 or r < 0.3:
        return rng.choice([
            f"cube([{_positive(rng, names)}, {_positive(rng, names)}, 1], center = {rng.choice(['true', 'false'])});",
            f"sphere(r = {_positive(rng, names)}{rng.choice(['', ', $fn = 8', ', $fa = 6'])});",
            f"cylinder(h = {_positive(rng, names)}, r1 = {_positive(rng, names)}, r2 = 1);",
        ])
    if r < 0.55:
        kind = rng.choice(["translate([{0}, {1}, {2}])", "rotate([{0}, {1}, {2}])", "rotate({0}, [{1}, {2}, 1])",
                           "scale([{3}, {3}, 1])", "mirror([{0}, 1, 0])"])
        return kind.format(_expr(rng, names), _expr(rng, names), _expr(rng, names), _positive(rng, names)) \
            + " " + _shape(rng, names, depth + 1)
    if r < 0.75:
        var = f"i{depth}"
        lo = rng.randint(-2, 1)
        return (f"for ({var} = [{lo}:{rng.choice(['', '0.5:', '2:'])}{lo + rng.randint(0, 3)}]) "
                f"{_shape(rng, [*names, var], depth + 1)}")
    if r < 0.85:
        return f"if ({_expr(rng, names)} > 0) {_shape(rng, names, depth + 1)} else {_shape(rng, names, depth + 1)}"
    op = rng.choice(["union", "difference", "intersection", "hull"])
    return f"{op}() {{ {_shape(rng, names, depth + 1)} {_shape(rng, names, depth + 1)} }}"


def random_program(seed: int) -> str:
    rng = random.Random(seed)
    lines = [f"a = {_num(rng)};", f"b = {_expr(rng, ['a'])};", "function f(x, y = 2) = x * y + a;",
             f"module part(s, t = {_num(rng)}) {{ {_shape(rng, ['s', 't', 'a'], 1)} }}"]
    if rng.random() < 0.4:
        lines.append(f"$fn = {rng.choice([5, 8, 12, 30])};")
    for _ in range(rng.randint(1, 3)):
        lines.append(rng.choice([_shape(rng, ["a", "b"], 0), f"part({_expr(rng, ['a', 'b'])});",
                                 "translate([f(a), f(b, 3), 0]) part(s = b, t = 3);"]))
    return "\n".join(lines) + "\n"


def color_names() -> str:
    """Every colour name OpenSCAD knows (the CSS keywords, as matplotlib lists them, and
    ``transparent``), in upper and lower case, and the hexadecimal forms."""
    from matplotlib.colors import CSS4_COLORS

    names = [*sorted(CSS4_COLORS), "transparent"]
    text = "".join(f'translate([{i}, 0, 0]) color("{n if i % 3 else n.upper()}") cube(1);\n' for i, n in enumerate(names))
    return text + ('color("#ff8000") cube(1);\ncolor("#f80") cube(1);\ncolor("#12345678") cube(1);\n'
                   'color("#abcd") cube(1);\ncolor("red", 0.5) cube(1);\ncolor(c = "Blue", alpha = 0.25) sphere(1);\n')


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    cases = {**HAND, "color_names": color_names()}
    for seed in range(24):
        cases[f"random_{seed:02d}"] = random_program(seed)
    for name, text in cases.items():
        scad = OUT / f"{name}.scad"
        scad.write_text(text)
        (OUT / f"{name}.csg").write_text(scad_to_csg(scad))
    for name, (text, files) in FILES.items():
        lib = OUT / f"{name}.lib"
        for rel, body in files.items():
            (lib / rel).parent.mkdir(parents=True, exist_ok=True)
            (lib / rel).write_text(body)
        scad = OUT / f"{name}.scad"
        scad.write_text(text)
        saved = dict(os.environ)
        os.environ.update(fixture_env(lib))
        try:
            (OUT / f"{name}.csg").write_text(scad_to_csg(scad))
        finally:
            os.environ.clear()
            os.environ.update(saved)
    print(f"wrote {len(cases) + len(FILES)} programs and their exports to {OUT}")


if __name__ == "__main__":
    main()
