"""Load rate on OpenSCAD's own models: its examples and its test suite's ``testdata/scad``.

Usage, from the repository root::

    python benchmarks/openscad_own_models.py /usr/share/openscad/examples
    python benchmarks/openscad_own_models.py TESTDATA/scad --stl-cache /tmp/own_stl

``TESTDATA`` is OpenSCAD 2021.01's ``testdata`` folder (``git archive openscad-2021.01 testdata``
of the openscad/openscad repository: its ``scad`` models read the ``stl``, ``svg``, ``amf`` and
``image`` files beside them). A model counts when OpenSCAD's own STL export of it
(``openscad -o x.stl``, ``--timeout`` seconds, cached in ``--stl-cache``) has facets: a non-empty 3D
solid; 2D-only, empty, unparsable and crashing models are left out. Each counted model is then
read by :func:`isocsg.openscad.read_openscad` (no render), stopped after ``--timeout`` seconds.
``--models FILE`` takes the counted models from a list instead (paths relative to the folder, one
a line): ``benchmarks/openscad_own_models_testdata.txt`` is the list of the 173 non-empty 3D models
of the tag's ``testdata/scad``, classified so on the development machine. Printed: one line a
model (``OK``, ``FAIL`` with the first refusal, ``TIME``), the load rate and the histogram of
refusals.
"""

from __future__ import annotations

import argparse
import collections
import signal
import sys
import warnings
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _common import openscad_export  # noqa: E402


def _solid(model: Path, root: Path, cache: Path, timeout: float) -> bool:
    """Whether OpenSCAD's STL export of ``model`` has facets (exported once, then read from ``cache``)."""
    out = cache / ("._" + str(model.relative_to(root)).replace("/", "_") + ".stl")
    return openscad_export(model, out, timeout) and out.stat().st_size > 0 and b"facet" in out.read_bytes()[:4096]


class _Timeout(Exception):
    pass


def _alarm(*_: Any) -> None:
    raise _Timeout


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("root", type=Path, help="a folder of .scad models (searched recursively)")
    ap.add_argument("--stl-cache", type=Path, default=None, help="where OpenSCAD's STL exports are kept")
    ap.add_argument("--models", type=Path, default=None, help="the counted models, one relative path a line")
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds for one export and for one read")
    args = ap.parse_args()
    from isocsg.openscad import read_openscad

    warnings.simplefilter("ignore")
    root = args.root.resolve()
    cache = args.stl_cache or root / "_stl"
    if not args.models:
        cache.mkdir(parents=True, exist_ok=True)
    if args.models:
        models = [root / line.strip() for line in args.models.read_text().splitlines() if line.strip()]
    else:
        models = sorted(p for p in root.rglob("*.scad") if _solid(p, root, cache, args.timeout))
    signal.signal(signal.SIGALRM, _alarm)
    ok, why = 0, collections.Counter[str]()
    for model in models:
        name = model.relative_to(root)
        signal.alarm(int(args.timeout))
        try:
            read_openscad(model)
            ok += 1
            print("OK  ", name, flush=True)
        except _Timeout:
            why["over the time limit"] += 1
            print("TIME", name, flush=True)
        except Exception as exc:  # noqa: BLE001 - every refusal is a row of the histogram
            key = f"{type(exc).__name__}: {str(exc).splitlines()[0].split(': ', 2)[-1][:70]}"
            why[key] += 1
            print("FAIL", name, key, flush=True)
        finally:
            signal.alarm(0)
    print(f"\n{ok} of {len(models)} non-empty 3D models load ({100 * ok / max(len(models), 1):.1f} %)")
    for key, n in why.most_common():
        print(f"{n:4d}  {key}")


if __name__ == "__main__":
    main()
