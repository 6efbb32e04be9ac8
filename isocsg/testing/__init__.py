"""Exact reference answers for mesh Boolean test suites (see ``docs/testing_engines.md``).

- :func:`reference`: the exact figures of a primitive or CSG tree (volume, surface area with its
  error, bounds, sections, signed distances with certified bounds, silhouettes and depth maps);
- :func:`surface_area`, :func:`boundary_volume`, :func:`closed_form_area`;
- :func:`signed_distance`: the CSG combination and its certified bounds;
- :func:`compare_mesh`: an engine's mesh against the truth and the tessellation reference;
  :func:`true_topology` (an all-planar tree's from its exact boundary polygons,
  :mod:`isocsg.testing.planar_topology`) and :func:`compare_topology` (the topology alone);
- :mod:`isocsg.testing.strategies`: hypothesis strategies (the ``testing`` extra) and
  :func:`to_python`;
- :mod:`isocsg.testing.plugin`: pytest fixtures.
"""

from .._lazy import lazy_exports

# Loaded on first use (the pytest plugin imports this package in every session of an install).
_EXPORTS: dict[str, str] = {
    **dict.fromkeys(["AreaResult", "boundary_volume", "closed_form_area", "surface_area"], ".area"),
    **dict.fromkeys(["MeshComparison", "Topology", "compare_mesh", "compare_topology", "topology", "true_topology"],
                    ".compare"),
    **dict.fromkeys(["DistanceResult", "signed_distance"], ".distance"),
    **dict.fromkeys(["Reference", "SectionReference", "reference"], ".figures"),
    "to_python": ".strategies",
}

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
    "compare_topology",
    "reference",
    "signed_distance",
    "surface_area",
    "to_python",
    "topology",
    "true_topology",
]

__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)
