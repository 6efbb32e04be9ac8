"""Soft shadows from area and polyhedron light sources (Nishita and Nakamae 1983).

Light sources live in :mod:`isocsg.lighting.area`; Lambert's contour
integral in :mod:`isocsg.shadows.lambert`; occluder decomposition in
:mod:`isocsg.shadows.occluders`; the exact illuminance and shadow states in
:mod:`isocsg.shadows.direct`; half-tone images in :mod:`isocsg.shadows.halftone`;
illuminance grids, their statistics and figures in :mod:`isocsg.shadows.luxmap`,
:mod:`isocsg.shadows.luxstats` and :mod:`isocsg.shadows.luxplot`; interreflections (a radiosity solve
over patches) in :mod:`isocsg.shadows.radiosity`, :mod:`isocsg.shadows.patches` and
:mod:`isocsg.shadows.form_factors`.

The names below are imported on first use: ``from isocsg.shadows import AreaLight``
loads the light sources only.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import lazy_exports

_EXPORTS: dict[str, str] = {
    **dict.fromkeys(["AreaLight", "PolyhedronLight"], "..lighting.area"),
    **dict.fromkeys(["illuminance", "shadow_state", "illuminance_and_state", "LIT", "PENUMBRA", "UMBRA"], ".direct"),
    **dict.fromkeys(["edge_terms", "polygon_illuminance", "rings_illuminance"], ".lambert"),
    **dict.fromkeys(["ConvexPiece", "convex_pieces", "shadow_pieces"], ".occluders"),
    **dict.fromkeys(["HalftoneResult", "render_halftone"], ".halftone"),
    **dict.fromkeys(["ShadowVolumes", "shadow_volumes"], ".volumes"),
    **dict.fromkeys(["LuxGrid", "LuxMap", "IsoluxLine", "illuminance_map", "save_luxmap_png"], ".luxmap"),
    **dict.fromkeys(["LuxStats", "lux_statistics", "save_luxmap_csv"], ".luxstats"),
    **dict.fromkeys(["plot_luxmap", "save_luxmap_figure"], ".luxplot"),
    "Room": ".patches",
    **dict.fromkeys(["Interreflections", "RadiositySolution", "solve_radiosity", "indirect_illuminance"], ".radiosity"),
    **dict.fromkeys(["point_form_factor", "polygon_form_factor"], ".form_factors"),
}

# Written out for linters and type checkers: the keys of _EXPORTS (tests/test_public_api.py).
__all__ = [
    "LIT",
    "PENUMBRA",
    "UMBRA",
    "AreaLight",
    "ConvexPiece",
    "HalftoneResult",
    "Interreflections",
    "IsoluxLine",
    "LuxGrid",
    "LuxMap",
    "LuxStats",
    "PolyhedronLight",
    "RadiositySolution",
    "Room",
    "ShadowVolumes",
    "convex_pieces",
    "edge_terms",
    "illuminance",
    "illuminance_and_state",
    "illuminance_map",
    "indirect_illuminance",
    "lux_statistics",
    "plot_luxmap",
    "point_form_factor",
    "polygon_form_factor",
    "polygon_illuminance",
    "render_halftone",
    "rings_illuminance",
    "save_luxmap_csv",
    "save_luxmap_figure",
    "save_luxmap_png",
    "shadow_pieces",
    "shadow_state",
    "shadow_volumes",
    "solve_radiosity"
]

__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)

if TYPE_CHECKING:
    from ..lighting.area import AreaLight, PolyhedronLight
    from .direct import (
        LIT,
        PENUMBRA,
        UMBRA,
        illuminance,
        illuminance_and_state,
        shadow_state,
    )
    from .form_factors import point_form_factor, polygon_form_factor
    from .halftone import HalftoneResult, render_halftone
    from .lambert import edge_terms, polygon_illuminance, rings_illuminance
    from .luxmap import IsoluxLine, LuxGrid, LuxMap, illuminance_map, save_luxmap_png
    from .luxplot import plot_luxmap, save_luxmap_figure
    from .luxstats import LuxStats, lux_statistics, save_luxmap_csv
    from .occluders import ConvexPiece, convex_pieces, shadow_pieces
    from .patches import Room
    from .radiosity import Interreflections, RadiositySolution, indirect_illuminance, solve_radiosity
    from .volumes import ShadowVolumes, shadow_volumes
