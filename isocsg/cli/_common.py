"""Helpers shared by the sub-commands: the parser class, sizes, progress bars, rendering."""

from __future__ import annotations

import argparse
import dataclasses
import functools
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any, NoReturn

from ..errors import InvalidParameterError

if TYPE_CHECKING:
    from ..scene.model import Scene

__all__ = [
    "ArgumentParser",
    "add_common_render_options",
    "apply_overrides",
    "check_outputs",
    "compile_notice",
    "load_scene_argument",
    "parse_size",
    "progress_bar",
    "render_scene",
    "write_outputs",
]

ProgressCallback = Callable[[int, int], None]


class ArgumentParser(argparse.ArgumentParser):
    """An argparse parser whose usage errors are one line and exit with code 2."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def parse_size(text: str) -> tuple[int, int]:
    """``"640x480"`` -> ``(640, 480)``; an argparse ``type``."""
    parts = text.lower().split("x")
    if len(parts) != 2 or not all(p.strip().isdigit() for p in parts):
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT such as 640x480, got {text!r}")
    return int(parts[0]), int(parts[1])


def add_common_render_options(parser: argparse.ArgumentParser) -> None:
    """``--size``, ``--contours`` and ``--no-progress``."""
    parser.add_argument("--size", type=parse_size, metavar="WxH",
                        help="image size in pixels, e.g. 640x480 (default: the scene's)")
    parser.add_argument(
        "--contours", type=int, metavar="N",
        help="isoluminance contours per light (default: the scene's render.contours)",
    )
    parser.add_argument("--no-progress", action="store_true", help="do not show the progress bar on stderr")


@contextmanager
def progress_bar(
    desc: str, *, enabled: bool = True, file: IO[str] | None = None, delay: float = 0.5,
) -> Iterator[ProgressCallback]:
    """A ``progress(done, total)`` callable that drives a tqdm bar on stderr.

    The bar appears only when the work lasts longer than ``delay`` seconds,
    so quick renders stay silent, and only on a terminal: redrawn with
    carriage returns, it would litter a log or a pipe. ``file`` is written to
    whatever it is (for tests).
    """
    bar: Any = None
    if file is None:
        stream = sys.stderr
        enabled = enabled and stream is not None and _is_terminal(stream)
    else:
        stream = file

    def update(done: int, total: int) -> None:
        nonlocal bar
        if not enabled:
            return
        if bar is None:
            # imported only when a bar shows: a quick render does without it
            from tqdm import tqdm

            bar = tqdm(total=total, desc=desc, file=stream, delay=delay, leave=False, unit="step")
        if bar.total != total:
            bar.total = total
        if done > bar.n:
            bar.update(done - bar.n)
        if done >= total:
            bar.refresh()  # show the finished state even within tqdm's refresh interval

    try:
        yield update
    finally:
        if bar is not None:
            bar.close()


def _is_terminal(stream: Any) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError, OSError):  # no isatty, or a closed stream
        return False


def load_scene_argument(path: str) -> Scene:
    """The scene a command line names: a ``.toml`` or ``.json`` file, or ``-`` for standard input.

    Standard input is read as a file is (UTF-8, at most
    :data:`~isocsg.scene.io.MAX_SCENE_FILE_BYTES` bytes); it is JSON when its
    first character other than white space is ``{``, TOML otherwise.

    Raises
    ------
    SceneFileError
        Naming the file (``<stdin>``) and what is wrong.
    """
    from ..scene.io import load_scene, loads_scene, read_scene_stream

    if path != "-":
        return load_scene(path)
    text, fmt = read_scene_stream(sys.stdin.buffer, source="<stdin>")
    return loads_scene(text, format=fmt, source="<stdin>")


def apply_overrides(scene: Scene, *, size: tuple[int, int] | None = None, contours: int | None = None) -> Scene:
    """The scene with the command line's image size and contour count."""
    if size is not None:
        scene = dataclasses.replace(scene, camera=scene.camera.with_size(*size))
    if contours is not None:
        scene = dataclasses.replace(scene, render=dataclasses.replace(scene.render, contours=contours))
    return scene


# The kernel paths (isocsg.kernels.PATHS) of each kind of render, and how the messages name them.
_COMPILE_PATHS = {"isoluminance": ("isoluminance",), "halftone": ("halftone",)}
_COMPILE_NAMES = {"isoluminance": "isoluminance", "halftone": "soft-shadow"}
_NOTICED: set[str] = set()


def kernels_cached(kind: str) -> bool:
    """Whether numba's on-disk cache holds the listed kernels of ``kind`` ("isoluminance" or "halftone").

    Reads the kernels' cache indexes (small files; see :mod:`isocsg.kernels`).
    """
    from ..kernels import missing_kernels

    return not missing_kernels(_COMPILE_PATHS[kind])


def compile_notice(kind: str, *, file: IO[str] | None = None) -> bool:
    """Compile the kernels of ``kind`` that the disk cache lacks, saying so on stderr; True if it did.

    A new install's first render would compile them one after the other on
    its first calls; they are compiled here first, on as many processes as
    there are cores (:func:`isocsg.kernels.compile_kernels`). Two lines are
    printed: what is compiled, on how many processes, with the time the
    recorded compile times predict; then the time it took. Nothing is said
    (or done) when the cache holds them, nor a second time in one process.
    """
    from ..kernels import compile_kernels

    if kind in _NOTICED:
        return False
    _NOTICED.add(kind)
    stream = file if file is not None else sys.stderr

    def start(kernels: int, processes: int, seconds: float) -> None:
        on = f"on {processes} processes" if processes > 1 else "on one process"
        idle = "on idle cores" if processes > 1 else "on an idle core"
        print(
            f"isocsg: compiling {kernels} {_COMPILE_NAMES[kind]} "
            f"kernel{'s' if kernels != 1 else ''} {on}, once for this install "
            f"(about {max(1, round(seconds))} s {idle}); later runs read them from numba's disk cache "
            "(`isocsg warmup` compiles every kind ahead of time)",
            file=stream,
            flush=True,
        )

    report = compile_kernels(_COMPILE_PATHS[kind], on_start=start)
    if report.kernels:
        print(f"isocsg: compiled in {report.seconds:.1f} s", file=stream, flush=True)
    return report.kernels > 0


def render_scene(scene: Scene, *, progress: ProgressCallback | None = None) -> Any:
    """Render with the method the scene asks for (``render.mode``).

    The kernels a new install lacks are compiled (:func:`compile_notice`) only when the render
    first needs a compiled kernel: a small model's render runs its kernels without numba
    (:mod:`isocsg._jit`) and compiles nothing.
    """
    from .._jit import on_first_compile

    kind = "halftone" if scene.render.mode == "halftone" else "isoluminance"
    on_first_compile(functools.partial(compile_notice, kind))
    if scene.render.mode == "halftone":
        from ..shadows.halftone import render_halftone

        return render_halftone(scene, progress=progress)
    from ..rendering import render

    return render(scene, progress=progress)


def check_outputs(png: str | Path | None, npy: str | Path | None = None) -> None:
    """Reject output names with the wrong extension before any work is done."""
    for path, suffix in ((png, ".png"), (npy, ".npy")):
        if path is not None and Path(path).suffix.lower() != suffix:
            raise InvalidParameterError(f"output file {str(path)!r} must end in {suffix}")
        if path is not None and Path(path).is_dir():  # found now, not after a long render
            raise InvalidParameterError(f"output file {str(path)!r} is a directory")


def write_outputs(result: Any, png: str | Path | None, npy: str | Path | None = None, *,
                  objects: Any = ()) -> list[Path]:
    """Write the PNG (and NPY) files of a render result, creating missing parent folders.

    The NPY file holds ``result.image`` (for a half-tone render: the illuminance E);
    the PNG shows ``result.display`` where the result has one (E times the scene's
    ``render.exposure``, clipped), else the image, in colour when one of ``objects`` (the scene's)
    is coloured (:mod:`isocsg.rendering.colors`).
    """
    from ..rendering.image import save_npy, save_png

    check_outputs(png, npy)
    written = []
    shown = getattr(result, "display", result.image)
    if not hasattr(result, "display") and objects:
        from ..rendering.colors import colored_image, is_colored

        if is_colored(objects):
            shown = colored_image(result, objects)
    for path, writer, image in ((png, save_png, shown), (npy, save_npy, result.image)):
        if path is None:
            continue
        p = Path(path)
        p.parent.mkdir(parents=True, exist_ok=True)
        writer(p, image)
        written.append(p)
    return written
