"""Exact reference answers for mesh Boolean test suites (see ``docs/testing_engines.md``).

- :func:`reference`: the exact figures of a primitive or CSG tree (volume, surface area with its
  error, bounds, sections, signed distances with certified bounds, silhouettes and depth maps);
- :func:`surface_area`, :func:`boundary_volume`, :func:`closed_form_area`;
- :func:`signed_distance`: the CSG combination and its certified bounds;
- :func:`compare_mesh`: an engine's mesh against the truth and the tessellation reference;
- :mod:`isocsg.testing.strategies`: hypothesis strategies (the ``testing`` extra) and
  :func:`to_python`;
- :mod:`isocsg.testing.plugin`: pytest fixtures.
"""

from .area import AreaResult, boundary_volume, closed_form_area, surface_area
from .compare import MeshComparison, Topology, compare_mesh, topology
from .distance import DistanceResult, signed_distance
from .reference import Reference, SectionReference, reference
from .strategies import to_python

__all__ = [
    "AreaResult",
    "DistanceResult",
    "MeshComparison",
    "Reference",
    "SectionReference",
    "Topology",
    "boundary_volume",
    "closed_form_area",
    "compare_mesh",
    "reference",
    "signed_distance",
    "surface_area",
    "to_python",
    "topology",
]
