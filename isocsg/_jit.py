"""Kernels compiled by numba on first need, run as plain Python or NumPy before.

A kernel is declared once, with :func:`njit` in place of ``numba.njit`` (same
options)::

    from .._jit import njit

    @njit(cache=True, nogil=True)
    def _orient(v, nrm, t): ...

Calling it runs, in this order of choice:

1. the numba-compiled kernel, once this process has compiled or loaded any
   kernel (numba's set-up is then paid, and a compiled kernel is the fastest);
2. else, for a small input, the kernel's own Python function (``py_func``) or
   its vectorised NumPy *twin* where one is registered (``@kernel.twin``): no
   numba at all. "Small" is the kernel's ``work`` estimate (loop iterations;
   by default the longest first dimension of its array arguments) at most
   :data:`isocsg.limits.JIT_PYTHON_WORK`, or :data:`isocsg.limits.JIT_TWIN_WORK`
   for a twin;
3. else numba is imported and the kernel compiled (or read from numba's disk
   cache), and every later call of every kernel takes path 1. So it is too once
   the process has spent :data:`isocsg.limits.JIT_PYTHON_SECONDS` of CPU time in
   Python runs of kernels (a model of many small leaves: each call is small, their
   sum is not).

A new process drawing a small model therefore never imports numba: numba's
import and its first dispatch cost about a second of CPU time, OpenSCAD's whole
preview a tenth of that. Kernels call one another as before: inside compiled
code a kernel is typed as its numba dispatcher (``_numba_type_``), so calls
between compiled kernels (``inline="always"`` included) stay compiled calls.

``ISOCSG_JIT`` (``auto``, ``numba`` or ``python``) or :func:`use` sets the
choice for the process: ``numba`` always compiles (the behaviour before this
module), ``python`` never does (for tests: the two give the same images).
:func:`on_first_compile` registers a callable run once, just before the
process's first compiled kernel (the command line's notice that a new install
compiles its kernels).
"""

from __future__ import annotations

import functools
import os
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any, TypeVar

from .errors import InvalidParameterError
from .limits import JIT_PYTHON_SECONDS, JIT_PYTHON_WORK, JIT_TWIN_WORK

__all__ = ["LazyKernel", "njit", "prange", "use", "mode", "engaged", "forget_spent", "on_first_compile"]

F = TypeVar("F", bound=Callable[..., Any])

#: ``range`` for the Python runs of kernels written with ``prange``.
prange = range

MODES = ("auto", "numba", "python")
_LOCK = threading.RLock()
_HOOKS: list[Callable[[], object]] = []
_state: dict[str, Any] = {"engaged": False, "mode": "", "spent": 0.0}
_local = threading.local()  # how deep in Python runs of kernels this thread is


def mode() -> str:
    """The process's choice: ``auto`` (default), ``numba`` or ``python`` (``ISOCSG_JIT`` or :func:`use`)."""
    if not _state["mode"]:
        value = os.environ.get("ISOCSG_JIT", "auto").strip().lower() or "auto"
        if value not in MODES:
            raise InvalidParameterError(f"ISOCSG_JIT must be one of {', '.join(MODES)}, got {value!r}")
        _state["mode"] = value
    return str(_state["mode"])


@contextmanager
def use(choice: str) -> Iterator[None]:
    """Run the block with kernels chosen as ``choice`` (one of ``auto``, ``numba``, ``python``).

    Tests compare the paths in one process: ``python`` runs no compiled kernel, ``numba`` no
    Python one, and ``auto`` starts as a new process does (no kernel compiled yet: small inputs
    run as Python until a large one compiles its kernel).

    Examples
    --------
    >>> with use("python"):
    ...     mode()
    'python'
    """
    if choice not in MODES:
        raise InvalidParameterError(f"choice must be one of {', '.join(MODES)}, got {choice!r}")
    with _LOCK:
        before, was_engaged, spent = mode(), _state["engaged"], _state["spent"]
        _state["mode"] = choice
        if choice == "auto":
            _state["engaged"], _state["spent"] = False, 0.0
    try:
        yield
    finally:
        with _LOCK:
            _state["mode"] = before
            _state["engaged"] = was_engaged or _state["engaged"]
            _state["spent"] = max(spent, _state["spent"])


def forget_spent() -> None:
    """Count the CPU time of Python runs of kernels from zero again (a process that has drawn
    only to warm up, such as the command line's server, then lets its children choose as a
    new process would)."""
    with _LOCK:
        _state["spent"] = 0.0


def engaged() -> bool:
    """Whether this process has compiled or loaded a kernel (every later call then runs compiled)."""
    return bool(_state["engaged"])


def on_first_compile(hook: Callable[[], object]) -> None:
    """Run ``hook()`` once, just before the process's first compiled kernel (at once if that was earlier)."""
    with _LOCK:
        if _state["engaged"]:
            hook()
        else:
            _HOOKS.append(hook)


def _engage() -> None:
    if _state["engaged"]:
        return
    with _LOCK:
        if _state["engaged"]:
            return
        _state["engaged"] = True
        hooks = list(_HOOKS)
        _HOOKS.clear()
    for hook in hooks:
        hook()


def _longest(args: tuple[Any, ...]) -> int:
    """The default work estimate: the longest first dimension of the array arguments."""
    n = 0
    for a in args:
        shape = getattr(a, "shape", None)
        if shape:
            n = max(n, int(shape[0]))
    return n


class LazyKernel:
    """A kernel: numba's dispatcher made on first need, its Python function (or a NumPy twin) before.

    Attributes
    ----------
    py_func : callable
        The kernel as written.
    options : dict
        The ``numba.njit`` options.
    """

    def __init__(self, py_func: Callable[..., Any], options: dict[str, Any],
                 work: Callable[..., float] | None = None) -> None:
        self.py_func = py_func
        self.options = options
        self._work = work
        self._twin: Callable[..., Any] | None = None
        self._dispatcher: Any = None
        self._quiet = options.get("error_model") == "numpy"
        functools.update_wrapper(self, py_func)

    def twin(self, func: F) -> F:
        """Register a vectorised NumPy version, run instead of the Python function for small inputs."""
        self._twin = func
        return func

    @property
    def dispatcher(self) -> Any:
        """numba's dispatcher of this kernel (imports numba; the first one in a process runs the hooks)."""
        _engage()
        if self._dispatcher is None:
            with _LOCK:
                if self._dispatcher is None:
                    import numba

                    self._dispatcher = numba.njit(**self.options)(self.py_func)
        return self._dispatcher

    @property
    def _numba_type_(self) -> Any:
        # How numba types this object where a compiled kernel names it: as its dispatcher.
        from numba.core import types

        return types.Dispatcher(self.dispatcher)

    def python(self, *args: Any) -> Any:
        """Run the NumPy twin, or else the Python function, whatever the input's size; the CPU
        time of outermost runs is added to the process's Python time (``JIT_PYTHON_SECONDS``)."""
        func = self._twin if self._twin is not None else self.py_func
        depth = getattr(_local, "depth", 0)
        _local.depth = depth + 1
        start = time.thread_time() if depth == 0 else 0.0  # a system call: outermost runs only
        try:
            if self._quiet:  # numba's error_model="numpy": a division by zero gives inf, silently
                import numpy as np

                with np.errstate(all="ignore"):
                    return func(*args)
            return func(*args)
        finally:
            _local.depth = depth
            if depth == 0:
                _state["spent"] += time.thread_time() - start

    def small(self, *args: Any) -> bool:
        """Whether ``args`` are small enough to run without numba."""
        work = self._work(*args) if self._work is not None else _longest(args)
        return work <= (JIT_TWIN_WORK if self._twin is not None else JIT_PYTHON_WORK)

    def __call__(self, *args: Any) -> Any:
        choice = _state["mode"] or mode()
        if choice == "numba" or (choice == "auto" and (
                _state["engaged"] or _state["spent"] > JIT_PYTHON_SECONDS or not self.small(*args))):
            return self.dispatcher(*args)
        return self.python(*args)

    def compile(self, signature: Any) -> Any:
        """Compile one specialisation now (numba's ``Dispatcher.compile``)."""
        return self.dispatcher.compile(signature)

    def __repr__(self) -> str:
        return f"<kernel {self.py_func.__module__}.{self.py_func.__qualname__}>"


def njit(*args: Any, work: Callable[..., float] | None = None, **options: Any) -> Any:
    """``numba.njit`` compiled on first need (see the module's docstring).

    Parameters
    ----------
    work : callable, keyword-only, optional
        ``work(*args)``: the call's cost in loop iterations (default: the
        longest first dimension of its array arguments), compared with
        :data:`isocsg.limits.JIT_PYTHON_WORK` (or ``JIT_TWIN_WORK`` with a twin).
    **options
        ``numba.njit``'s options (``cache``, ``nogil``, ``inline``, ...).
    """
    if args and callable(args[0]):
        return LazyKernel(args[0], options, work)

    def wrap(func: Callable[..., Any]) -> LazyKernel:
        return LazyKernel(func, options, work)

    return wrap

