"""Shared pytest set-up: off-screen VTK, a fixed, small thread count and the hypothesis profiles.

Property tests draw new random examples on every local run (the ``explore``
profile), so that each run searches further. With ``CI`` set in the
environment they run the ``ci`` profile instead: the same derandomized
examples on every machine, so that a continuous-integration result depends
on the commit alone. A failing example prints the ``@reproduce_failure``
blob to replay it.
"""

import os

from hypothesis import settings

# Off-screen VTK through EGL skips a slow X display probe on machines without a screen.
os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
os.environ.setdefault("NUMBA_NUM_THREADS", "2")

settings.register_profile("explore", print_blob=True)
settings.register_profile("ci", derandomize=True, print_blob=True)
settings.load_profile("ci" if os.environ.get("CI") else "explore")


def pytest_sessionfinish(session, exitstatus):
    """Release the cached manifold3d reference meshes before the interpreter shuts down.

    nanobind reports manifold3d objects still alive at exit as leaks.
    """
    import gc
    import sys

    geometry = sys.modules.get("test_csg_geometry")
    if geometry is not None:
        geometry.reference.cache_clear()
    gc.collect()
