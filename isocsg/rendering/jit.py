"""Options shared by the renderer's per-polygon and per-pixel numba kernels."""

from __future__ import annotations

from typing import Any

__all__ = ["RAW"]

# Options of the per-polygon kernels. They are compiled without numba's
# reference counting (``_nrt=False``): with it, every array handed to a helper
# or sliced into a row view costs two atomic operations per polygon, which
# was most of the cost of a small polygon (4x the set-up itself). These
# kernels allocate nothing; their thin entry points do.
RAW: dict[str, Any] = {"cache": True, "nogil": True, "_nrt": False}
# Constant flags are passed to these kernels as ``np.bool_(...)`` and
# ``np.int64(...)``: a bare ``True`` or ``-1`` is typed as a literal, and numba
# compiles one specialisation per literal value (the fill kernels four times
# over, most of a new install's first-render compile time).
