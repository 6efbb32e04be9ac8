"""A primitive kind defined outside the package: a capsule (a segment grown by a radius).

The capsule is written here, against the kind interface alone (:class:`isocsg.kinds.Primitive`),
registered with :func:`isocsg.kinds.register_kind`, and then rendered, sectioned, integrated,
used as a shadow occluder and read from a scene file, without any change to the package. The
references are independent of the library: the capsule's ray hits and the exact image from its
own closed forms, its volume ``pi r^2 h + 4/3 pi r^3``, its sections' areas, and the illuminance
under it by Monte Carlo over the light with exact segment-to-segment visibility.
"""

from __future__ import annotations

import math
import re
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar

import numpy as np
import pytest
from numpy.typing import ArrayLike, NDArray

sys.path.insert(0, str(Path(__file__).parent))

from reference.metrics import compare_images
from reference.raycaster import camera_rays

import isocsg
from isocsg import Camera, Cylinder, PointLight, Scene, Sphere
from isocsg._validation import scalar, vector3
from isocsg.bands.surface import Surface, orient_outward, ring_triangles
from isocsg.kinds import (
    ConvexPolyhedron,
    Primitive,
    RayHits,
    kind_named,
    register_kind,
    unregister_kind,
)


@dataclass(frozen=True, slots=True)
class Capsule(Primitive):
    """The points within ``radius`` of the segment ``a``-``b``."""

    a: tuple[float, float, float]
    b: tuple[float, float, float]
    radius: float
    kind: ClassVar[str] = "capsule"

    def __post_init__(self) -> None:
        object.__setattr__(self, "a", vector3("Capsule.a", self.a))
        object.__setattr__(self, "b", vector3("Capsule.b", self.b))
        object.__setattr__(self, "radius", scalar("Capsule.radius", self.radius, low=0.0))

    # the parts whose union it is: two balls and a cylinder
    def _parts(self) -> tuple[Sphere, Sphere, Cylinder]:
        a, b = np.asarray(self.a), np.asarray(self.b)
        return Sphere(self.a, self.radius), Sphere(self.b, self.radius), Cylinder(tuple((a + b) / 2), tuple(b - a), self.radius)

    @property
    def bounds(self) -> NDArray[np.float64]:
        a, b = np.asarray(self.a), np.asarray(self.b)
        return np.stack([np.minimum(a, b) - self.radius, np.maximum(a, b) + self.radius])

    def extent(self, n: ArrayLike) -> tuple[float, float]:
        w = np.asarray(n, dtype=np.float64)
        pa, pb = float(np.asarray(self.a) @ w), float(np.asarray(self.b) @ w)
        return min(pa, pb) - self.radius, max(pa, pb) + self.radius

    def breakpoints(self, n: ArrayLike) -> NDArray[np.float64]:
        # the section's area has kinks where the plane leaves each ball's cap for the side
        w = np.asarray(n, dtype=np.float64)
        out = [*self.extent(w)]
        for part in self._parts():
            out += list(part.breakpoints(w))
        return np.asarray(out)

    @property
    def volume(self) -> float:
        h = float(np.linalg.norm(np.subtract(self.b, self.a)))
        return math.pi * self.radius**2 * h + 4.0 / 3.0 * math.pi * self.radius**3

    def _closest(self, p: NDArray[np.float64]) -> NDArray[np.float64]:
        a, b = np.asarray(self.a), np.asarray(self.b)
        ab = b - a
        t = np.clip((p - a) @ ab / (ab @ ab), 0.0, 1.0)
        return a + t[:, None] * ab  # type: ignore[no-any-return]

    def signed_distance(self, points: ArrayLike) -> NDArray[np.float64]:
        p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        return np.linalg.norm(p - self._closest(p), axis=1) - self.radius  # type: ignore[no-any-return]

    def normals_at(self, points: ArrayLike) -> NDArray[np.float64]:
        p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        d = p - self._closest(p)
        return d / np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-300)  # type: ignore[no-any-return]

    def intersect_rays(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:
        # convex: the union of its parts' intervals along a ray is one interval
        hits = [p.intersect_rays(origins, directions) for p in self._parts()]
        t_in = np.stack([h.t_in for h in hits])
        t_out = np.stack([np.where(h.hit, h.t_out, -np.inf) for h in hits])
        i, j = np.argmin(t_in, axis=0), np.argmax(t_out, axis=0)
        rows = np.arange(t_in.shape[1])
        n_in = np.stack([h.n_in for h in hits])[i, rows]
        n_out = np.stack([h.n_out for h in hits])[j, rows]
        return RayHits(t_in[i, rows], np.where(np.isfinite(t_in[i, rows]), t_out[j, rows], -np.inf), n_in, n_out)

    def section(self, frame: NDArray[np.float64], resolution: int, area_exact: bool = False) -> Any:
        import shapely

        parts = [p.section(frame, resolution, area_exact) for p in self._parts()]
        return shapely.convex_hull(shapely.union_all([g for g in parts if not g.is_empty]))

    def to_polyhedron(self, resolution: int = 64) -> ConvexPolyhedron:
        a, b = self._parts()[:2]
        return ConvexPolyhedron(np.vstack([a.to_polyhedron(resolution).hull_vertices, b.to_polyhedron(resolution).hull_vertices]))

    def band_surface(self, lights, contours, eye, shininess, weights=(1.0, 1.0), segments=None, *, hidden=None) -> Surface:
        # a latitude-longitude mesh: the hemisphere around b, the side, the hemisphere around a
        a, b = np.asarray(self.a), np.asarray(self.b)
        w = (b - a) / np.linalg.norm(b - a)
        u = np.cross(w, [1.0, 0.0, 0.0] if abs(w[0]) < 0.9 else [0.0, 1.0, 0.0])
        u /= np.linalg.norm(u)
        v = np.cross(w, u)
        n_lat, n_lon = 48, 128
        theta = np.pi / 2 * np.arange(1, n_lat + 1) / n_lat
        phi = 2 * np.pi * np.arange(n_lon) / n_lon
        rings, centres = [], []
        for th, c in [(t, b) for t in theta] + [(np.pi - t, a) for t in theta[::-1]]:
            rings.append(np.sin(th) * (np.cos(phi)[:, None] * u + np.sin(phi)[:, None] * v) + np.cos(th) * w)
            centres.append(np.broadcast_to(c, (n_lon, 3)))
        normals = np.vstack([w[None, :], *rings, -w[None, :]])
        centre = np.vstack([b[None, :], *centres, a[None, :]])
        origin = (a + b) / 2
        vertices = centre + self.radius * normals - origin
        triangles = orient_outward(vertices, normals, ring_triangles(len(rings), n_lon))
        return Surface(vertices, normals, triangles, origin, np.zeros(len(vertices), np.int64))

    @property
    def area(self) -> float:
        h = float(np.linalg.norm(np.subtract(self.b, self.a)))
        return 2.0 * math.pi * self.radius * h + 4.0 * math.pi * self.radius**2

    def to_dict(self) -> dict[str, Any]:
        return {"capsule": {"a": list(self.a), "b": list(self.b), "radius": self.radius}}

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:
        raise NotImplementedError


CAPSULE = dict(a=(-0.6, -0.2, 0.1), b=(0.7, 0.3, 0.4), radius=0.45)


@pytest.fixture(scope="module", autouse=True)
def registered():
    register_kind("capsule", required=("a", "b", "radius"))(Capsule)
    yield
    unregister_kind("capsule")


# ----------------------------------------------------------------------------- independent references


def capsule_hits(a, b, r, o, d):
    """Entry parameter and normal of unit rays against the capsule, in closed form."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    ab = b - a
    h = np.linalg.norm(ab)
    w = ab / h
    best = np.full(len(o), np.inf)
    normal = np.zeros_like(o)
    # the side: |(x - a) x w| = r with 0 <= (x - a) . w <= h
    oa = o - a
    dp = d - (d @ w)[:, None] * w
    op = oa - (oa @ w)[:, None] * w
    qa, qb, qc = (dp * dp).sum(1), (dp * op).sum(1), (op * op).sum(1) - r * r
    disc = qb * qb - qa * qc
    ok = (disc >= 0) & (qa > 1e-15)
    t = np.where(ok, (-qb - np.sqrt(np.where(ok, disc, 0))) / np.where(ok, qa, 1), np.inf)
    s = (oa + np.where(ok, t, 0.0)[:, None] * d) @ w
    ok &= (s >= 0) & (s <= h) & (t > 0)
    best = np.where(ok, t, best)
    x = o + np.where(ok, t, 0)[:, None] * d
    normal = np.where(ok[:, None], (x - a - ((x - a) @ w)[:, None] * w) / r, normal)
    for c in (a, b):  # the end balls
        oc = o - c
        bb = (oc * d).sum(1)
        disc = bb * bb - ((oc * oc).sum(1) - r * r)
        ok = disc >= 0
        t = np.where(ok, -bb - np.sqrt(np.where(ok, disc, 0)), np.inf)
        better = ok & (t > 0) & (t < best)
        best = np.where(better, t, best)
        normal = np.where(better[:, None], (o + np.where(better, t, 0)[:, None] * d - c) / r, normal)
    return best, normal


def segment_distance(p0, p1, q0, q1):
    """Distances between segments p0-p1 (rows) and the segment q0-q1 (closed form, clamped)."""
    d1, d2, rr = p1 - p0, q1 - q0, p0 - q0
    a, e, f = (d1 * d1).sum(1), float(d2 @ d2), rr @ d2
    c, b = (d1 * rr).sum(1), d1 @ d2
    den = a * e - b * b
    s = np.where(den > 1e-15, np.clip((b * f - c * e) / np.where(den > 1e-15, den, 1), 0, 1), 0.0)
    t = (b * s + f) / e
    t_c = np.clip(t, 0, 1)
    s = np.where(t < 0, np.clip(-c / a, 0, 1), np.where(t > 1, np.clip((b - c) / a, 0, 1), s))
    return np.linalg.norm(p0 + s[:, None] * d1 - (q0 + t_c[:, None] * d2), axis=1)


# ----------------------------------------------------------------------------- the tests


def test_registered_kind_is_read_live():
    kind = kind_named("capsule")
    assert kind is not None and kind.cls is Capsule
    assert "capsule" in isocsg.scene.io.shape_kinds()
    assert Capsule(**CAPSULE).kind == "capsule"


def test_renders():
    cap = Capsule(**CAPSULE)
    camera = Camera((2.5, -3.5, 2.0), (0.05, 0.05, 0.25), width=96, height=96, fov=35)
    light = PointLight((3.0, -1.0, 4.0))
    image = isocsg.render(Scene(camera, [light], [cap]), contours=64).image
    o, d = camera_rays(camera)
    t, n = capsule_hits(CAPSULE["a"], CAPSULE["b"], CAPSULE["radius"], o.reshape(-1, 3), d.reshape(-1, 3))
    p = o.reshape(-1, 3) + np.where(np.isfinite(t), t, 0)[:, None] * d.reshape(-1, 3)
    lv = np.asarray(light.position) - p
    cos_i = np.maximum(0.0, (n * lv).sum(1) / np.linalg.norm(lv, axis=1))
    exact = np.where(np.isfinite(t), 0.1 + 0.8 * cos_i, np.nan).reshape(image.shape)
    result = compare_images(image, exact)
    assert result.iou >= 0.99 and result.fraction >= 0.98, result.summary()


def test_sections():
    cap = Capsule(**CAPSULE)
    a, b, r = np.asarray(CAPSULE["a"]), np.asarray(CAPSULE["b"]), CAPSULE["radius"]
    h = float(np.linalg.norm(b - a))
    w = (b - a) / h
    # across the axis between the ends: a disc; through the axis: a rectangle and two half discs
    across = isocsg.section(cap, (a + b) / 2, w, resolution=512).area
    assert across == pytest.approx(math.pi * r * r, rel=1e-4)
    side = np.cross(w, [0.0, 0.0, 1.0])
    along = isocsg.section(cap, (a + b) / 2, side / np.linalg.norm(side), resolution=512).area
    assert along == pytest.approx(2 * r * h + math.pi * r * r, rel=1e-4)
    # a Boolean with a built-in kind goes through the same program
    cut = isocsg.section(cap - Sphere(tuple(b), r), (a + b) / 2, w, resolution=512).area
    assert cut == pytest.approx(math.pi * r * r, rel=1e-4)


def test_volume():
    cap = Capsule(**CAPSULE)
    assert isocsg.volume(cap, tol=1e-5) == pytest.approx(cap.volume, rel=1e-4)
    # and as a leaf of a tree, against manifold-free closed forms: half of it cut away by a box
    a, b = np.asarray(CAPSULE["a"]), np.asarray(CAPSULE["b"])
    far = isocsg.Box(tuple((a + b) / 2 + [0, 0, 50.0]), (100.0, 100.0, 100.0))
    assert isocsg.volume(cap | far, tol=1e-5) == pytest.approx(cap.volume + far.volume - isocsg.volume(cap & far, tol=1e-5), rel=1e-4)


def test_shadows():
    cap = Capsule(a=(-0.5, 0.0, 1.0), b=(0.5, 0.2, 1.1), radius=0.25)
    light = isocsg.AreaLight([(-1.0, -1.0, 3.0), (-1.0, 1.0, 3.0), (1.0, 1.0, 3.0), (1.0, -1.0, 3.0)], radiance=1.0)
    points = np.array([[0.0, 0.0, 0.0], [0.3, 0.4, 0.0], [1.2, -0.3, 0.0], [-0.4, 0.6, 0.0]])
    normal = np.array([0.0, 0.0, 1.0])
    got = isocsg.illuminance(points, normal, light, [cap], resolution=128)
    # Monte Carlo over the light: stratified samples, visibility by the segment distance
    m = 400
    g = (np.stack(np.meshgrid(np.arange(m), np.arange(m), indexing="ij"), -1).reshape(-1, 2) + 0.5) / m
    samples = np.column_stack([-1.0 + 2.0 * g[:, 0], -1.0 + 2.0 * g[:, 1], np.full(len(g), 3.0)])
    ref = []
    for p in points:
        v = samples - p
        d2 = (v * v).sum(1)
        cos_p, cos_l = v[:, 2] / np.sqrt(d2), v[:, 2] / np.sqrt(d2)
        seen = segment_distance(np.broadcast_to(p, samples.shape), samples, np.asarray(cap.a), np.asarray(cap.b)) > cap.radius
        ref.append(4.0 * float(np.mean(seen * cos_p * cos_l / d2)))
    unshadowed = isocsg.illuminance(points, normal, light)
    assert np.all(np.asarray(ref) < unshadowed)  # every point is partly shadowed
    assert got == pytest.approx(ref, rel=1e-2, abs=1e-4)


def test_scene_file(tmp_path):
    text = f"""
[camera]
eye = [2.5, -3.5, 2.0]
target = [0.0, 0.0, 0.2]
width = 32
height = 32

[[lights]]
kind = "point"
position = [3.0, -1.0, 4.0]

[[objects]]
shape = {{ difference = [{{ capsule = {{ a = {list(CAPSULE['a'])}, b = {list(CAPSULE['b'])}, radius = {CAPSULE['radius']} }} }},
                         {{ sphere = {{ center = [0.7, 0.3, 0.4], radius = 0.2 }} }}] }}
"""
    path = tmp_path / "capsule.toml"
    path.write_text(text)
    scene = isocsg.load_scene(path)
    cap = scene.objects[0].shape.children[0]
    assert isinstance(cap, Capsule) and cap == Capsule(**CAPSULE)
    # and written back
    again = isocsg.load_scene(isocsg.save_scene(scene, tmp_path / "again.toml"))
    assert again.objects[0].shape == scene.objects[0].shape
    with pytest.raises(isocsg.SceneFileError, match=re.escape("objects[0].shape.difference[0].capsule.radius: missing required field")):
        isocsg.scene.loads_scene(text.replace(f", radius = {CAPSULE['radius']}", ""))


def test_projection_hull_and_area_through_the_kind_interface():
    # a horizontal capsule: its section by z = 0 runs through its axis (a rectangle and two half discs),
    # polygonised from its own section() since it has no exact form
    from isocsg.shapes2d import area
    from isocsg.shapes2d.projection import projection
    from isocsg.testing import closed_form_area, surface_area

    cap = Capsule(a=(-0.5, 0.1, 0.0), b=(0.5, 0.3, 0.0), radius=0.3)
    h, r = float(np.linalg.norm(np.subtract(cap.b, cap.a))), cap.radius
    assert cap.exact_form() is None
    assert area(projection(cap, cut=True)) == pytest.approx(2 * r * h + math.pi * r * r, rel=1e-5)
    with pytest.raises(isocsg.NotExactError, match=re.escape("projection: the outline of a Capsule is not computed exactly")):
        projection(cap)
    with pytest.raises(isocsg.NotExactError, match=re.escape("hull: a hull of a Capsule is not an exact union")):
        isocsg.hull(cap, Sphere((2.0, 0.0, 0.0), 0.5))
    # its area: Steiner's formula, the radius derivative of its volume pi r^2 h + 4/3 pi r^3
    dr = 1e-6
    thicker, thinner = (Capsule(cap.a, cap.b, r + s) for s in (dr, -dr))
    assert closed_form_area(cap) == pytest.approx((thicker.volume - thinner.volume) / (2 * dr), rel=1e-8)
    assert surface_area(cap).value == closed_form_area(cap) and surface_area(cap).exact
    # a tree needs its surface parametrised: the default refuses, naming the kind
    with pytest.raises(isocsg.InvalidParameterError, match=re.escape("no surface parametrisation for the kind Capsule")):
        surface_area(cap - Sphere(cap.b, 0.2))
    with pytest.raises(isocsg.InvalidParameterError, match=re.escape("surface area: no closed form for the kind BallPair")):
        closed_form_area(BallPair((-1.0, 0.0, 1.0), (1.0, 0.0, 1.0), 0.4))


@dataclass(frozen=True, slots=True)
class BallPair(Primitive):
    """Two disjoint balls as one solid: the smallest non-convex kind (two intervals per ray)."""

    a: tuple[float, float, float]
    b: tuple[float, float, float]
    radius: float
    kind: ClassVar[str] = "ball_pair"
    convex: ClassVar[bool] = False
    max_intervals: ClassVar[int] = 2

    def _balls(self) -> tuple[Sphere, Sphere]:
        return Sphere(self.a, self.radius), Sphere(self.b, self.radius)

    @property
    def bounds(self) -> NDArray[np.float64]:
        lo = np.minimum(*(s.bounds[0] for s in self._balls()))
        return np.stack([lo, np.maximum(*(s.bounds[1] for s in self._balls()))])

    def signed_distance(self, points: ArrayLike) -> NDArray[np.float64]:
        return np.minimum(*(s.signed_distance(points) for s in self._balls()))

    def ray_intervals(self, origins: ArrayLike, directions: ArrayLike) -> NDArray[np.float64]:
        out = np.concatenate([s.ray_intervals(origins, directions) for s in self._balls()], axis=1)
        order = np.argsort(np.where(np.isnan(out[:, :, 0]), np.inf, out[:, :, 0]), axis=1)
        return np.take_along_axis(out, order[:, :, None], axis=1)

    def convex_pieces(self, resolution: int = 64) -> list[ConvexPolyhedron]:
        return [s.to_polyhedron(resolution) for s in self._balls()]


def test_non_convex_kind_rays_and_shadows():
    pair = BallPair((-1.0, 0.0, 1.0), (1.0, 0.0, 1.0), 0.4)
    iv = pair.ray_intervals([[-3.0, 0.0, 1.0], [0.0, 0.0, 5.0]], [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])
    assert iv.shape == (2, 2, 2)
    assert np.allclose(iv[0], [[1.6, 2.4], [3.6, 4.4]]) and np.isnan(iv[1]).all()
    # as an occluder: its convex pieces, exactly the shadows of the two balls
    light = isocsg.AreaLight([(-2.0, -1.0, 3.0), (-2.0, 1.0, 3.0), (2.0, 1.0, 3.0), (2.0, -1.0, 3.0)])
    points = np.array([[-1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [1.3, 0.2, 0.0]])
    got = isocsg.illuminance(points, (0.0, 0.0, 1.0), light, [pair])
    want = isocsg.illuminance(points, (0.0, 0.0, 1.0), light, list(pair._balls()))
    assert np.allclose(got, want, rtol=1e-12, atol=1e-15)
    assert np.all(got < isocsg.illuminance(points, (0.0, 0.0, 1.0), light))
    # and as a leaf of a tree: each piece cut like a leaf of its own
    cut = isocsg.Box((0.0, 0.0, 0.7), (4.0, 2.0, 0.6))
    a, b = pair._balls()
    got = isocsg.illuminance(points, (0.0, 0.0, 1.0), light, [pair - cut])
    want = isocsg.illuminance(points, (0.0, 0.0, 1.0), light, [(a | b) - cut])
    assert np.allclose(got, want, rtol=1e-12, atol=1e-15)
