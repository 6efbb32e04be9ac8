"""Running the ``openscad`` program: ``.scad`` to ``.csg`` (and to STL for comparisons).

OpenSCAD evaluates its language (modules, loops, functions) and exports the
flattened tree as ``.csg`` text, which :mod:`isocsg.openscad.parser` reads.
The program is optional: only ``.scad`` input needs it, and its absence is a
:class:`~isocsg.errors.MissingDependencyError` saying what to install.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

from ..errors import MissingDependencyError, OpenSCADError

__all__ = ["find_openscad", "scad_to_csg", "export_mesh", "OPENSCAD_TIMEOUT"]

#: Seconds one ``openscad`` run may take before it is stopped.
OPENSCAD_TIMEOUT = 600.0

_INSTALL = "install OpenSCAD (Debian/Ubuntu: apt install openscad; see https://openscad.org/downloads.html)"


def find_openscad() -> str:
    """Path of the ``openscad`` program (``$ISOCSG_OPENSCAD`` or the one on ``PATH``).

    Raises
    ------
    MissingDependencyError
        If it is not installed.
    """
    exe = os.environ.get("ISOCSG_OPENSCAD") or shutil.which("openscad")
    if not exe or not Path(exe).exists():
        raise MissingDependencyError(f"reading .scad files needs the openscad program, which was not found: {_INSTALL}")
    return exe


def _run(args: list[str], source: str, timeout: float) -> None:
    import subprocess  # here: a file read without the program does not load it

    exe = find_openscad()
    try:
        done = subprocess.run(
            [exe, *args], capture_output=True, text=True, encoding="utf-8", errors="replace",  # any bytes in messages
            timeout=timeout, stdin=subprocess.DEVNULL, check=False,
        )
    except subprocess.TimeoutExpired:
        raise OpenSCADError(f"{source}: openscad did not finish within {timeout:g} s") from None
    except OSError as exc:
        raise MissingDependencyError(f"could not run {exe}: {exc.strerror or exc}; {_INSTALL}") from None
    if done.returncode != 0:
        lines = [ln for ln in (done.stderr or "").splitlines() if ln.strip()]
        detail = "; ".join(ln for ln in lines if "ERROR" in ln) or (lines[-1] if lines else "no message")
        raise OpenSCADError(f"{source}: openscad failed (exit {done.returncode}): {detail}")


def scad_to_csg(path: str | os.PathLike[str], *, timeout: float = OPENSCAD_TIMEOUT) -> str:
    """The ``.csg`` text that ``openscad -o model.csg -D '$preview=false' model.scad`` exports.

    ``$preview`` is false as in OpenSCAD's render and STL export (its ``.csg`` export alone runs
    as a preview): a model's ``if ($preview)`` cut-away or helper is not part of the solid. Runs
    in a temporary directory, which is removed afterwards.

    Raises
    ------
    MissingDependencyError
        If ``openscad`` is not installed.
    OpenSCADError
        If it fails (a syntax error of the ``.scad`` file, ...) or times out.
    """
    p = Path(path)
    if not p.is_file():
        raise OpenSCADError(f"{p}: not a file")
    import tempfile

    with tempfile.TemporaryDirectory(prefix="isocsg-openscad-") as tmp:
        out = Path(tmp) / "model.csg"
        # the .csg export runs as a preview ($preview true); the model is what a render exports
        _run(["-o", str(out), "-D", "$preview=false", str(p.resolve())], str(p), timeout)
        if not out.is_file():
            raise OpenSCADError(f"{p}: openscad wrote no .csg file")
        return out.read_text(encoding="utf-8", errors="replace")


def export_mesh(
    path: str | os.PathLike[str],
    out: str | os.PathLike[str],
    *,
    fn: int | None = None,
    timeout: float = OPENSCAD_TIMEOUT,
) -> Path:
    """``openscad --render -o OUT.stl model.scad`` (OpenSCAD's own mesh, for comparisons).

    Parameters
    ----------
    path : path-like
        The ``.scad`` or ``.csg`` model.
    out : path-like
        Mesh file to write; the format follows the extension (``.stl``, ``.off``).
    fn : int, optional
        Overrides ``$fn`` (segments per full circle) on the command line.
    """
    args = ["--render", "-o", str(out)]
    if fn is not None:
        args += ["-D", f"$fn={int(fn)}"]
    _run([*args, str(Path(path).resolve())], str(path), timeout)
    return Path(out)
