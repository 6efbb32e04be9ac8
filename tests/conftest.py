"""Shared pytest set-up: off-screen VTK, a fixed, small thread count and the hypothesis profiles.

Property tests draw new random examples on every local run (the ``explore``
profile), so that each run searches further. With ``CI`` set in the
environment they run the ``ci`` profile instead: the same derandomized
examples on every machine, so that a continuous-integration result depends
on the commit alone. A failing example prints the ``@reproduce_failure``
blob to replay it. ``ISOCSG_SEARCH_NOSHRINK=1`` reports failures as found,
without shrinking them (long local searches, where shrinking a slow example
can take longer than the search).
"""

import os

from hypothesis import settings

# Off-screen VTK through EGL skips a slow X display probe on machines without a screen.
os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
os.environ.setdefault("NUMBA_NUM_THREADS", "2")
# Every command line the tests run (in-process or in a subprocess) runs in its own process, as
# before the command line's server; tests/test_cli_server.py turns it on in its own directory.
os.environ["ISOCSG_SERVER"] = "0"

from hypothesis import Phase

_SEARCH_PHASES = tuple(p for p in Phase if p not in (Phase.shrink, Phase.explain))
settings.register_profile("explore", print_blob=True)
settings.register_profile("search", print_blob=True, phases=_SEARCH_PHASES)
settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")
else:
    settings.load_profile("search" if os.environ.get("ISOCSG_SEARCH_NOSHRINK") else "explore")


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
