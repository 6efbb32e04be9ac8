"""The kernel listing and the compilation of kernels on several processes (isocsg.kernels).

Judges: numba's own dispatchers (the signatures a render really compiles, the
kernels its disk cache holds), observed in fresh processes.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from isocsg.errors import InvalidParameterError
from isocsg.kernels import PATHS, compile_kernels, path_kernels

ROOT = Path(__file__).resolve().parents[1]


def _python(code: str, **env: str) -> str:
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600,
                          env={**os.environ, "PYTHONPATH": str(ROOT), **env})
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


# What a fresh process compiles when it renders a path: every isocsg dispatcher with its signatures.
_OBSERVE = """
import json, sys
from numba.core.registry import CPUDispatcher
from isocsg._jit import LazyKernel
from isocsg.kernels import render_path
render_path({path!r})
seen = {{}}
for name, mod in list(sys.modules.items()):
    if name.startswith("isocsg"):
        for attr, d in vars(mod).items():
            d = d._dispatcher if isinstance(d, LazyKernel) else d
            if isinstance(d, CPUDispatcher) and d.py_func.__module__ == name and d.signatures:
                seen[name + "." + attr] = sorted(repr(tuple(s)) for s in d.signatures)
print(json.dumps(seen))
"""


@pytest.mark.parametrize("path", PATHS)
def test_the_listing_is_what_a_render_compiles(path: str) -> None:
    from isocsg.kernels import _callees

    seen = json.loads(_python(_OBSERVE.format(path=path)).splitlines()[-1])
    listed: dict[str, set[str]] = {}
    for k in path_kernels(path):
        listed.setdefault(k.qualname, set()).add(repr(tuple(k.signature())))
    callees = set().union(*(_callees(k.dispatcher()) for k in path_kernels(path)))
    for name, sigs in listed.items():  # nothing stale: every listed signature is used
        assert sigs <= set(seen.get(name, ())), name
    for name, sigs in seen.items():  # nothing missing: all else is compiled with a listed kernel
        assert name in callees, f"{name} is compiled by a {path} render but not listed"
        if name in listed:
            assert set(sigs) <= listed[name], name


# The lightest kernels instead of the listing (a few seconds of compiling in all, more than a
# worker's start, so that a worker gets a share); two processes, whatever the machine's load.
_COMPILE = """
import io, json
import isocsg.kernels as K
from isocsg.cli._common import compile_notice, kernels_cached
light = []
for k in sorted(K.path_kernels("isoluminance"), key=lambda k: k.seconds):
    if sum(x.seconds for x in light) < 3.0:
        light.append(k)
K._listing = lambda: {p: tuple(light) for p in K.PATHS}
K._default_processes = lambda: 2
print(json.dumps([kernels_cached("isoluminance"), len(K.missing_kernels()), len(light)]))
f = io.StringIO()
said = compile_notice("isoluminance", file=f)
in_memory = sum(tuple(k.signature()) in k.dispatcher().overloads for k in light)
print(json.dumps([said, f.getvalue(), len(K.missing_kernels()), in_memory, kernels_cached("isoluminance")]))
r = K.compile_kernels(["isoluminance"], processes=2)
print(json.dumps([r.kernels, r.processes]))
"""


def test_two_processes_fill_the_disk_cache_and_say_so(tmp_path: Path) -> None:
    lines = _python(_COMPILE, NUMBA_CACHE_DIR=str(tmp_path)).splitlines()
    before, after, again = (json.loads(line) for line in lines[-3:])
    n = before[2]
    assert before == [False, n, n] and n >= 4
    said, text, missing, in_memory, cached = after
    message = text.splitlines()
    assert said and len(message) == 2, text
    assert re.fullmatch(rf"isocsg: compiling {n} isoluminance kernels on 2 processes, once for this install "
                        r"\(about \d+ s on idle cores\); later runs read them from numba's disk cache .*", message[0]), text
    assert re.fullmatch(r"isocsg: compiled in \d+\.\d s", message[1]), text
    # All are on disk; this process holds only its own share: the worker compiled the rest.
    assert missing == 0 and cached and 0 < in_memory < n
    assert again == [0, 1]
    assert list(tmp_path.rglob("*.nbc"))


@pytest.mark.parametrize("cores,load,expected", [(2, 0.0, 2), (2, 0.4, 2), (2, 0.6, 1), (2, 12.0, 1), (8, 3.2, 5), (1, 0.0, 1)])
def test_one_process_per_idle_core(monkeypatch: pytest.MonkeyPatch, cores: int, load: float, expected: int) -> None:
    import isocsg.kernels as K

    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: set(range(cores)))
    monkeypatch.setattr(K, "_busy_cores", lambda: load)
    assert K._default_processes() == expected


def test_busy_cores_are_measured_now_within_the_machine() -> None:
    import isocsg.kernels as K

    busy = K._busy_cores(0.05)
    assert 0.0 <= busy <= (os.cpu_count() or 1) + 1e-9


def test_busy_cores_fall_back_to_the_load_average(monkeypatch: pytest.MonkeyPatch) -> None:
    import builtins

    import isocsg.kernels as K

    real_open = builtins.open

    def no_proc_stat(path, *args, **kwargs):
        if str(path) == "/proc/stat":
            raise FileNotFoundError(path)
        return real_open(path, *args, **kwargs)

    monkeypatch.setattr(builtins, "open", no_proc_stat)
    monkeypatch.setattr(os, "getloadavg", lambda: (3.5, 1.0, 1.0))
    assert K._busy_cores(0.0) == 3.5


def test_errors() -> None:
    with pytest.raises(InvalidParameterError, match=re.escape("path must be one of isoluminance, surface, halftone, got 'x'")):
        path_kernels("x")
    with pytest.raises(InvalidParameterError, match=re.escape("processes must be at least 1, got 0")):
        compile_kernels(processes=0)


def test_a_stale_entry_is_left_to_the_first_call() -> None:
    from isocsg.kernels import Kernel, _compile

    k = path_kernels("isoluminance")[0]
    stale = Kernel(k.module, k.name, k.args[:-1], k.seconds)  # one argument short: numba refuses it
    _compile([stale])  # no error: the kernel is compiled when first called
    assert tuple(stale.signature()) not in k.dispatcher().overloads


@pytest.mark.parametrize("path", PATHS)
def test_every_listed_kernel_is_where_the_listing_says(path: str) -> None:
    # A kernel whose module moved would make the cache check (missing_kernels) say all is cached.
    from numba.core.registry import CPUDispatcher

    for k in path_kernels(path):
        assert isinstance(k.dispatcher(), CPUDispatcher), f"{k.module}.{k.name}"
