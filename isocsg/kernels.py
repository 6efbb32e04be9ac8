"""Compiling isocsg's numba kernels ahead of their first call, on several processes.

numba compiles a kernel on its first call and keeps the machine code in its
on-disk cache (``cache=True``; next to the package, or in ``NUMBA_CACHE_DIR``),
so only a new install's first render waits for it: about 13 s of CPU time for
the kernels of one CSG image. Those kernels are listed in
``isocsg/data/kernels.json`` (module, name, argument types and the CPU
seconds their compilation took), recorded from the built-in scenes by ``python -m isocsg.kernels --record``.

:func:`compile_kernels` compiles the listed kernels that the cache lacks,
shared between this process and worker processes (one per further idle core, measured over 0.2 s): each
worker fills the disk cache, this process keeps its share in memory, waits
for the workers, and later calls load their kernels from the cache. Kernels
that call the same compiled kernel are compiled by one process, so none is
compiled twice. The ``isocsg`` command line does this before a render whose
kernels are not cached; ``isocsg warmup`` does it for every path.

Examples
--------
>>> [k.name for k in path_kernels("isoluminance") if k.name == "fill_projected"]
['fill_projected']
"""

from __future__ import annotations

import importlib
import json
import math
import os
import subprocess
import sys
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cache
from importlib import resources
from typing import Any

from .errors import InvalidParameterError

__all__ = ["PATHS", "Kernel", "CompileReport", "path_kernels", "missing_kernels", "compile_kernels", "render_path"]

#: The rendering paths whose kernels are listed: a CSG image resolved per pixel
#: (``isocsg render``, ``isocsg demo``), a later view through the clipped CSG
#: surface, and a soft-shadow (half-tone) image.
PATHS = ("isoluminance", "surface", "halftone")

# A worker process starts (Python, numpy, numba and the kernels' modules) in
# about this many seconds before it compiles: its share is smaller by as much.
_WORKER_START_SECONDS = 1.0


@dataclass(frozen=True, slots=True)
class Kernel:
    """One compiled specialisation of a numba kernel.

    Attributes
    ----------
    module, name : str
        Where the dispatcher lives (``isocsg.rendering.raster``, ``fill_projected``).
    args : tuple of str
        The argument types, as numba writes them (``repr`` of a numba type).
    seconds : float
        CPU seconds its compilation took when recorded (the kernels it calls included).
    """

    module: str
    name: str
    args: tuple[str, ...]
    seconds: float

    @property
    def qualname(self) -> str:
        """``module.name``."""
        return f"{self.module}.{self.name}"

    def dispatcher(self) -> Any:
        """The numba dispatcher (imports its module; a kernel declared with :func:`isocsg._jit.njit` gives its own)."""
        found = getattr(importlib.import_module(self.module), self.name)
        return getattr(found, "dispatcher", found)

    def signature(self) -> tuple[Any, ...]:
        """The argument types as numba types."""
        return tuple(_parse_type(a) for a in self.args)


@dataclass(frozen=True, slots=True)
class CompileReport:
    """What :func:`compile_kernels` did.

    Attributes
    ----------
    kernels : int
        Kernels compiled (those the cache already held are not counted).
    processes : int
        Processes that compiled them (this one included).
    seconds : float
        Wall-clock seconds it took.
    """

    kernels: int
    processes: int
    seconds: float


@cache
def _listing() -> dict[str, tuple[Kernel, ...]]:
    text = resources.files("isocsg").joinpath("data/kernels.json").read_text(encoding="utf-8")
    raw = json.loads(text)
    return {
        path: tuple(Kernel(k["module"], k["name"], tuple(k["args"]), float(k["seconds"])) for k in raw[path])
        for path in PATHS
    }


def path_kernels(path: str) -> tuple[Kernel, ...]:
    """The kernels a render of ``path`` (one of :data:`PATHS`) compiles first, heaviest first.

    Raises
    ------
    InvalidParameterError
        For an unknown path.
    """
    if path not in PATHS:
        raise InvalidParameterError(f"path must be one of {', '.join(PATHS)}, got {path!r}")
    return _listing()[path]


def _kernels(paths: Sequence[str]) -> list[Kernel]:
    seen: dict[tuple[str, tuple[str, ...]], Kernel] = {}
    for path in paths:
        for k in path_kernels(path):
            seen.setdefault((k.qualname, k.args), k)
    return list(seen.values())


def missing_kernels(paths: Sequence[str] = ("isoluminance",)) -> list[Kernel]:
    """The listed kernels of ``paths`` that numba's disk cache does not hold.

    Reads each kernel's cache index (a small file). Where numba's cache
    cannot be read this way (another numba version), returns an empty list:
    the kernels are then compiled on first call, as without this module.
    """
    try:
        return [k for k in _kernels(paths) if not _is_cached(k)]
    except Exception:  # noqa: BLE001 - numba internals: compile on first call rather than fail
        return []


def _is_cached(k: Kernel) -> bool:
    disp = k.dispatcher()
    key = disp._cache._index_key(k.signature(), disp.targetctx.codegen())
    return key in disp._cache._cache_file._load_index()


@cache
def _type_names() -> dict[str, Any]:
    """numba's type names, for :func:`_parse_type` (built once: a warm render checks every listed kernel)."""
    from numba.core import types

    names = {n: v for n, v in vars(types).items() if not n.startswith("_")}
    names["bool"] = types.boolean
    return names


@cache
def _parse_type(text: str) -> Any:
    # The text comes from the package's own listing; no builtins are reachable.
    return eval(text, {"__builtins__": {}}, _type_names())  # noqa: S307


def _groups(kernels: Sequence[Kernel]) -> list[list[Kernel]]:
    """Kernels joined when they call a common compiled kernel (one process compiles them all)."""
    parent = list(range(len(kernels)))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    owner: dict[str, int] = {}
    for i, k in enumerate(kernels):
        for name in _callees(k.dispatcher()):
            if name in owner:
                parent[root(i)] = root(owner[name])
            else:
                owner[name] = i
    groups: dict[int, list[Kernel]] = {}
    for i, k in enumerate(kernels):
        groups.setdefault(root(i), []).append(k)
    return list(groups.values())


def _callees(dispatcher: Any) -> set[str]:
    """``module.name`` of a kernel and of every compiled kernel it may call, read from the names its code uses."""
    from numba.core.registry import CPUDispatcher

    from ._jit import LazyKernel

    seen: set[str] = set()
    todo = [dispatcher]
    while todo:
        d = todo.pop()
        f = d.py_func
        name = f"{f.__module__}.{f.__qualname__}"
        if name in seen:
            continue
        seen.add(name)
        for g in (f.__globals__.get(n) for n in f.__code__.co_names):
            if isinstance(g, LazyKernel):
                todo.append(g.dispatcher)
            elif isinstance(g, CPUDispatcher):
                todo.append(g)
    return seen


def _shares(kernels: Sequence[Kernel], processes: int) -> list[list[Kernel]]:
    """Groups dealt to ``processes`` shares, heaviest first to the least loaded (share 0 is this process's)."""
    load = [0.0] + [_WORKER_START_SECONDS] * (processes - 1)
    shares: list[list[Kernel]] = [[] for _ in range(processes)]
    for group in sorted(_groups(kernels), key=lambda g: -sum(k.seconds for k in g)):
        i = min(range(processes), key=lambda p: load[p])
        shares[i].extend(group)
        load[i] += sum(k.seconds for k in group)
    return shares


def _compile(kernels: Sequence[Kernel]) -> None:
    for k in kernels:
        try:
            k.dispatcher().compile(k.signature())
        except Exception:  # noqa: BLE001 - a stale listing (tests/test_kernels.py): compiled on first call instead
            pass


def _busy_cores(interval: float = 0.2) -> float:
    """How many cores other work keeps busy now: from ``/proc/stat`` over ``interval`` seconds,
    or the 1-minute load average where that file is missing.

    Not the load average alone: it lags by a minute, and a new install's first render comes right
    after ``pip install`` has kept a core busy, when the machine is idle again.
    """
    def ticks() -> tuple[int, int]:
        with open("/proc/stat", encoding="ascii") as f:
            fields = [int(x) for x in f.readline().split()[1:]]
        return sum(fields), fields[3] + (fields[4] if len(fields) > 4 else 0)  # total, idle + iowait

    try:
        total0, idle0 = ticks()
        time.sleep(interval)
        total1, idle1 = ticks()
    except (OSError, ValueError, IndexError):  # not Linux
        try:
            return os.getloadavg()[0]
        except (AttributeError, OSError):
            return 0.0
    if total1 <= total0:
        return 0.0
    return (1.0 - (idle1 - idle0) / (total1 - total0)) * (os.cpu_count() or 1)


def _default_processes() -> int:
    """One process per idle core: the cores this process may use less the cores busy now, at least 1.

    On a loaded machine a second process gets no more of it than one does,
    and costs its own start and numba's set-up (about 2 s of CPU time).
    """
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        cores = os.cpu_count() or 1
    return max(1, min(cores, math.floor(cores - _busy_cores() + 0.5)))


def compile_kernels(
    paths: Sequence[str] = ("isoluminance",),
    *,
    processes: int | None = None,
    progress: Callable[[int, int], None] | None = None,
    on_start: Callable[[int, int, float], None] | None = None,
) -> CompileReport:
    """Compile the listed kernels of ``paths`` that the disk cache lacks, on several processes.

    Parameters
    ----------
    paths : sequence of str, default ("isoluminance",)
        Items of :data:`PATHS`.
    processes : int, keyword-only, optional
        Processes that compile, this one included (default: one per idle
        core, the cores this process may use less those busy over the last
        0.2 s, at least one). Workers are started only when they have work.
    progress : callable, keyword-only, optional
        ``progress(done, total)`` after each kernel this process compiles,
        ``total`` counting every kernel compiled.
    on_start : callable, keyword-only, optional
        ``on_start(kernels, processes, seconds)`` before compiling, when there
        is something to compile: ``seconds`` is the wall time the recorded
        compile times predict (for a message).

    Returns
    -------
    CompileReport

    Raises
    ------
    InvalidParameterError
        For an unknown path or a non-positive ``processes``.

    Examples
    --------
    >>> compile_kernels(["isoluminance"]).processes >= 1   # doctest: +SKIP
    True
    """
    for p in paths:
        path_kernels(p)
    if processes is not None and int(processes) < 1:
        raise InvalidParameterError(f"processes must be at least 1, got {processes!r}")
    start = time.perf_counter()
    todo = missing_kernels(paths)
    # Idle cores are measured (0.2 s) only when there is something to compile: a warm render
    # calls this too.
    n = (_default_processes() if processes is None else int(processes)) if todo else 1
    shares = [s for s in _shares(todo, min(n, len(todo))) if s] if todo else []
    if on_start is not None and todo:
        loads = [sum(k.seconds for k in s) + (_WORKER_START_SECONDS if i else 0.0) for i, s in enumerate(shares)]
        on_start(len(todo), len(shares), max(loads))
    # The workers import this very package, wherever it was imported from.
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(p for p in (root, os.environ.get("PYTHONPATH")) if p)}
    workers = []
    for share in shares[1:]:
        spec = json.dumps([[k.module, k.name, list(k.args)] for k in share])
        # A worker fills the disk cache and exits; its output would only be numba's warnings.
        workers.append(subprocess.Popen(
            [sys.executable, "-m", "isocsg.kernels", "--compile", spec],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env,
        ))
    try:
        mine = shares[0] if shares else []
        for i, k in enumerate(mine):
            _compile([k])
            if progress is not None:
                progress(i + 1, len(todo))
    finally:
        for w in workers:
            w.wait()
    # A worker that failed leaves its kernels to be compiled on first call.
    return CompileReport(len(todo), max(1, len(shares)), time.perf_counter() - start)


# ----------------------------------------------------------------- recording
def _record(path: str) -> list[dict[str, Any]]:
    """Render ``path``'s built-in scene in this process and list the kernels it compiled at top level."""
    import threading

    from numba.core import event

    local = threading.local()
    top: list[dict[str, Any]] = []

    class Listener(event.Listener):
        def on_start(self, ev: Any) -> None:
            local.__dict__.setdefault("stack", []).append(time.thread_time())

        def on_end(self, ev: Any) -> None:
            t0 = local.stack.pop()
            f = ev.data["dispatcher"].py_func
            if not local.stack and f.__module__.startswith("isocsg."):
                top.append({
                    "module": f.__module__, "name": f.__qualname__, "args": [repr(a) for a in ev.data["args"]],
                    "seconds": round(time.thread_time() - t0, 2),
                })

    event.register("numba:compile", Listener())
    render_path(path)
    return sorted(top, key=lambda k: -k["seconds"])


def render_path(path: str) -> None:
    """Render the built-in scene of ``path`` as the kernel listing was recorded (the demo at full size, or tiny),
    every kernel compiled (:func:`isocsg._jit.use`: ``"numba"``), as a large model's render compiles them."""
    from dataclasses import replace

    from ._jit import use
    from .scene.io import builtin_scene_path, load_scene

    path_kernels(path)
    with use("numba"):
        if path == "halftone":
            from .shadows.halftone import render_halftone

            s = load_scene(builtin_scene_path("halftone"))
            render_halftone(replace(s, camera=replace(s.camera, width=24, height=18)))
            return
        from .rendering import Renderer

        s = load_scene(builtin_scene_path("demo"))
        if path == "surface":
            small = replace(s, camera=replace(s.camera, width=48, height=36), render=replace(s.render, contours=8))
            Renderer(csg="surface").render(small)
        else:
            Renderer().render(s)


def _main(argv: Sequence[str]) -> int:
    if len(argv) == 2 and argv[0] == "--compile":
        _compile([Kernel(m, n, tuple(a), 0.0) for m, n, a in json.loads(argv[1])])
        return 0
    if len(argv) == 2 and argv[0] == "--record-path":
        print(json.dumps(_record(argv[1])))
        return 0
    if len(argv) == 1 and argv[0] == "--record":
        # Each path in a new process with an empty cache, so that every kernel it uses compiles.
        import tempfile

        out = {}
        for path in PATHS:
            with tempfile.TemporaryDirectory() as tmp:
                env = {**os.environ, "NUMBA_CACHE_DIR": tmp}
                done = subprocess.run([sys.executable, "-m", "isocsg.kernels", "--record-path", path],
                                      env=env, check=True, capture_output=True, text=True)
            out[path] = json.loads(done.stdout.strip().splitlines()[-1])
        # One kernel a line: reviewable diffs.
        lines = ["{"]
        for i, (path, kernels) in enumerate(out.items()):
            lines.append(f' "{path}": [')
            lines += ["  " + json.dumps(k) + ("," if j < len(kernels) - 1 else "") for j, k in enumerate(kernels)]
            lines.append(" ]" + ("," if i < len(out) - 1 else ""))
        print("\n".join(lines) + "\n}")
        return 0
    print("usage: python -m isocsg.kernels --record > isocsg/data/kernels.json", file=sys.stderr)
    return 2


if __name__ == "__main__":
    raise SystemExit(_main(sys.argv[1:]))
