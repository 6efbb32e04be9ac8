"""Shared pytest set-up: off-screen VTK and a fixed, small thread count."""

import os

# Off-screen VTK through EGL skips a slow X display probe on machines without a screen.
os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
os.environ.setdefault("NUMBA_NUM_THREADS", "2")
