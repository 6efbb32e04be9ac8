"""Mesh helpers the kinds share: manifold3d, loaded on first use, and frames onto an axis."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import MissingDependencyError

__all__ = ["manifold3d_module", "rotation_to_axis"]


def manifold3d_module() -> Any:
    """The manifold3d module (a core dependency, imported when a mesh is first built)."""
    try:
        import manifold3d
    except ImportError as exc:  # pragma: no cover - manifold3d is a core dependency
        raise MissingDependencyError("to_manifold needs manifold3d: pip install manifold3d") from exc
    return manifold3d


def rotation_to_axis(axis: NDArray[np.float64]) -> NDArray[np.float64]:
    """A rotation matrix that maps +z onto the unit vector ``axis``.

    Parameters
    ----------
    axis : ndarray, shape (3,)
        Unit target direction.

    Returns
    -------
    ndarray, shape (3, 3)
        Orthonormal, determinant +1, with ``R @ (0, 0, 1) == axis``.

    Examples
    --------
    >>> R = rotation_to_axis(np.array([1.0, 0.0, 0.0]))
    >>> np.round(R @ [0, 0, 1], 12).tolist()
    [1.0, 0.0, 0.0]
    """
    a = np.asarray(axis, dtype=np.float64)
    a = a / np.linalg.norm(a)
    helper = np.array([1.0, 0.0, 0.0]) if abs(a[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    x = np.cross(helper, a)
    x /= np.linalg.norm(x)
    y = np.cross(a, x)
    return np.column_stack([x, y, a])
