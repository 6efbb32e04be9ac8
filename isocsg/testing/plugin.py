"""pytest fixtures: the truth for a solid in one line.

Registered as a pytest plugin through the ``pytest11`` entry point ``isocsg`` (installed
with isocsg), or by ``pytest_plugins = ["isocsg.testing.plugin"]`` in a ``conftest.py``:

.. code-block:: python

    def test_union(isocsg_reference, isocsg_compare):
        tree = Sphere((0, 0, 0), 1) | Sphere((0, 0, 0.75), 1)
        assert abs(my_engine_volume(tree) - isocsg_reference(tree).volume) < 1e-3
        assert isocsg_compare(my_engine_mesh(tree), tree, segments=64).ok
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import pytest

if TYPE_CHECKING:  # the plugin loads with every pytest session: isocsg itself only when a fixture is used
    from ..kinds import Solid
    from .compare import MeshComparison
    from .figures import Reference

__all__ = ["isocsg_compare", "isocsg_reference"]


@pytest.fixture(scope="session")
def isocsg_reference() -> Callable[..., Reference]:
    """``isocsg_reference(solid, tol=1e-9)``: :func:`isocsg.testing.reference`, kept per solid for the session."""
    from .figures import reference

    cache: dict[tuple[Solid, float], Reference] = {}

    def get(solid: Solid, tol: float = 1e-9) -> Reference:
        key = (solid, float(tol))
        if key not in cache:
            cache[key] = reference(solid, tol=tol)
        return cache[key]

    return get


@pytest.fixture(scope="session")
def isocsg_compare(isocsg_reference: Callable[..., Reference]) -> Callable[..., MeshComparison]:
    """``isocsg_compare(mesh, solid, **kw)``: :func:`isocsg.testing.compare_mesh` with the session's references."""

    from .compare import compare_mesh

    def run(mesh: Any, solid: Solid, **kw: Any) -> MeshComparison:
        return compare_mesh(mesh, solid, ref=isocsg_reference(solid), **kw)

    return run
