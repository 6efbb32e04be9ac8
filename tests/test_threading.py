"""Callers in threads are safe under every numba threading layer.

numba's ``workqueue`` layer aborts the whole process when two threads launch
parallel kernels at once. The illuminance kernel is serial and runs on plain
threads: it launches no parallel kernel, whichever layer is asked for. Each
layer runs in a child process (a process chooses its layer once).
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

SCRIPT = textwrap.dedent(
    """
    import numpy as np
    from concurrent.futures import ThreadPoolExecutor
    import numba
    from isocsg import Box, illuminance
    from isocsg.shadows import AreaLight

    lamp = AreaLight([(-.5, -.5, 2.5), (-.5, .5, 2.5), (.5, .5, 2.5), (.5, -.5, 2.5)], radiance=1000.0)
    occ = [Box((0.3, 0.2, 0.4), (0.6, 0.6, 0.8))]
    rng = np.random.default_rng(0)
    chunks = [np.c_[rng.uniform(-2, 2, (2000, 2)), np.zeros(2000)] for _ in range(8)]
    with ThreadPoolExecutor(4) as pool:
        threaded = list(pool.map(lambda p: illuminance(p, (0, 0, 1), [lamp], occ), chunks))
    serial = [illuminance(p, (0, 0, 1), [lamp], occ) for p in chunks]
    assert all(np.array_equal(a, b) for a, b in zip(threaded, serial))
    assert all((a > 0).any() and (a == 0).any() for a in serial)  # lit and umbra nodes in each chunk
    try:
        layer = numba.threading_layer()
    except ValueError:  # no parallel kernel was launched
        layer = "none"
    print("layer", layer)
    """
)


@pytest.mark.parametrize("layer", ["workqueue", "omp"])
def test_threaded_callers_do_not_abort(layer: str) -> None:
    env = dict(os.environ, NUMBA_THREADING_LAYER=layer, PYTHONPATH=str(ROOT))
    proc = subprocess.run([sys.executable, "-c", SCRIPT], env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert proc.stdout.split() == ["layer", "none"]
