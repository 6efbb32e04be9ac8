"""``include <path>`` and ``use <path>`` for :mod:`isocsg.openscad.evaluate`, as OpenSCAD 2021.01 does them.

OpenSCAD's lexer reads both: ``include <f>`` inserts the tokens of ``f`` in place (its own
``include``/``use`` resolved relative to its directory), ``use <f>`` becomes a statement of the
file being read (only at its top level: elsewhere it is a syntax error). A path is looked up in
the directory of the file that names it, then in each directory of ``OPENSCADPATH``, the user
library folder (``$HOME/.local/share/OpenSCAD/libraries``) and ``/usr/share/openscad/libraries``
(:func:`library_dirs`). A file found nowhere (OpenSCAD warns), a cycle, a file that is not
``.scad`` or not UTF-8, files nested more than :data:`MAX_FILE_DEPTH` deep and more than
:data:`MAX_LIBRARY_BYTES` of text in all raise :class:`~isocsg.openscad.scad_syntax.Declined`.
"""

from __future__ import annotations

import os
from pathlib import Path

from .scad_syntax import Declined

__all__ = ["MAX_FILE_DEPTH", "MAX_LIBRARY_BYTES", "Files", "library_dirs"]

#: Deepest nesting of included and used files.
MAX_FILE_DEPTH = 8
#: Most bytes of text read from included and used files in all, as much as a file read in-process
#: (a large library's own parse, about 3 ms a KiB,
#: outweighs an ``openscad`` run).
MAX_LIBRARY_BYTES = 1 << 16


def library_dirs() -> list[Path]:
    """OpenSCAD 2021.01's library folders on Linux, in the order it searches them."""
    dirs = [Path(d) for d in os.environ.get("OPENSCADPATH", "").split(os.pathsep) if d]
    home = os.environ.get("HOME")
    if home:
        dirs.append(Path(home) / ".local" / "share" / "OpenSCAD" / "libraries")
    dirs.append(Path("/usr/share/openscad/libraries"))
    return dirs


class Files:
    """The files an evaluation reads: found as OpenSCAD finds them, their bytes counted."""

    def __init__(self, root: Path | None) -> None:
        self.root = root
        self.bytes = 0

    def find(self, name: str, source: Path | None, open_files: tuple[Path, ...]) -> Path:
        """The file ``include``/``use <name>`` names in a file of directory ``source``."""
        if source is None:
            raise Declined("include or use in text without a path")
        if not name or not name.endswith(".scad"):
            raise Declined(f"include or use of {name!r} (not a .scad file)")
        local = Path(name)
        candidates = [local] if local.is_absolute() else [source / local, *(d / local for d in library_dirs())]
        for c in candidates:
            try:
                if not c.exists() or c.is_dir():
                    continue
                found = c.resolve()
            except OSError:
                continue
            if found in open_files:
                raise Declined(f"{name}: a circular include or use")
            return found
        raise Declined(f"can't open {name} (OpenSCAD warns)")

    def read(self, path: Path, open_files: tuple[Path, ...]) -> str:
        """The text of a file found, counted against :data:`MAX_LIBRARY_BYTES`."""
        if len(open_files) > MAX_FILE_DEPTH:
            raise Declined("include or use nested too deeply")
        try:
            # the size first: a huge file is declined without being read
            if self.bytes + path.stat().st_size > MAX_LIBRARY_BYTES:
                raise Declined("too much work (included or used files too large)")
            data = path.read_bytes()
            self.bytes += len(data)
            if self.bytes > MAX_LIBRARY_BYTES:  # (grown since its size was read)
                raise Declined("too much work (included or used files too large)")
            return data.decode("utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise Declined(f"{path}: {exc}") from None
