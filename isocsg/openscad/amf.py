"""``import("part.amf")``: an AMF file (plain or zipped XML) as OpenSCAD 2021.01 reads it.

OpenSCAD's ``import_amf.cc`` makes one polygon soup of each ``<object>`` (the triangles of all its
``<volume>`` elements over its ``<vertices>``), ignores the ``unit`` attribute and colours, and
unites the objects. Here each object is a :class:`~isocsg.kinds.TriangleMesh` (where its volumes
share faces, so that the soup is no closed mesh, the union of its volumes' meshes), and the
objects are united (:class:`~isocsg.csg.Union`).
"""

from __future__ import annotations

import zipfile
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..errors import InvalidGeometryError

if TYPE_CHECKING:
    from xml.etree import ElementTree

__all__ = ["read_amf"]


def _xml(path: Path) -> ElementTree.Element:
    from xml.etree import ElementTree  # here: a model without AMF files does not load it

    try:
        if zipfile.is_zipfile(path):
            with zipfile.ZipFile(path) as z:
                names = [n for n in z.namelist() if not n.endswith("/")]
                if not names:
                    raise InvalidGeometryError(f"AMF file {str(path)!r}: an empty zip archive")
                return ElementTree.fromstring(z.read(names[0]))
        return ElementTree.parse(path).getroot()
    except (ElementTree.ParseError, zipfile.BadZipFile, OSError) as exc:
        raise InvalidGeometryError(f"AMF file {str(path)!r} could not be read: {exc}") from None


def _number(node: ElementTree.Element, tag: str, path: Path) -> float:
    text = node.findtext(tag)
    try:
        return float(text) if text is not None else 0.0
    except ValueError:
        raise InvalidGeometryError(f"AMF file {str(path)!r}: <{tag}> is not a number, got {text!r}") from None


def _object_solid(obj: ElementTree.Element, path: Path) -> Any:
    from ..csg import Union
    from ..kinds import TriangleMesh
    from ..kinds.mesh_io import reoriented

    points = np.array([[_number(c, t, path) for t in ("x", "y", "z")]
                       for c in obj.iterfind("mesh/vertices/vertex/coordinates")], dtype=np.float64).reshape(-1, 3)
    volumes = []
    for volume in obj.iterfind("mesh/volume"):
        tris = [[int(_number(t, v, path)) for v in ("v1", "v2", "v3")] for t in volume.iterfind("triangle")]
        if tris:
            volumes.append(np.asarray(tris, dtype=np.int64))
    if not volumes:
        return None
    faces = np.vstack(volumes)
    if faces.min() < 0 or faces.max() >= len(points):
        raise InvalidGeometryError(f"AMF file {str(path)!r}: a triangle names a vertex out of 0 .. {len(points) - 1}")
    points, same = np.unique(points, axis=0, return_inverse=True)  # repeated points are one (as OpenSCAD's grid)
    same = same.reshape(-1)
    faces, volumes = same[faces], [same[v] for v in volumes]
    try:
        return TriangleMesh(points, faces)
    except InvalidGeometryError as exc:
        if len(volumes) == 1:
            if "not consistently oriented" in str(exc) or "wind inwards" in str(exc):
                return reoriented(points, faces)
            raise
        return Union(*[TriangleMesh(points, v) for v in volumes])  # volumes sharing faces: their union


def read_amf(path: str | Path) -> Any:
    """The solid of an AMF file: the union of its objects (see the module notes).

    Raises
    ------
    InvalidGeometryError
        If the file cannot be read, holds no triangles, or a mesh is not a valid closed solid.
    """
    from ..csg import Union

    p = Path(path)
    root = _xml(p)
    solids = [s for s in (_object_solid(obj, p) for obj in root.iterfind("object")) if s is not None]
    if not solids:
        raise InvalidGeometryError(f"AMF file {str(p)!r} holds no triangles")
    return solids[0] if len(solids) == 1 else Union(*solids)
