"""Shared helpers of the benchmark scripts: median timing and plain-text tables."""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable, Sequence
from typing import Any

__all__ = ["median_time", "format_table", "print_table", "fmt_seconds", "fmt_rate"]


def median_time(fn: Callable[[], Any], repeats: int, *, warmup: int = 0) -> tuple[float, Any]:
    """Median wall-clock seconds of ``fn()`` over ``repeats`` calls (after ``warmup`` calls), and the last result."""
    out = None
    for _ in range(warmup):
        out = fn()
    times = []
    for _ in range(max(1, repeats)):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def fmt_seconds(s: float | None) -> str:
    """Seconds with a unit that keeps three significant digits (``-`` for None)."""
    if s is None:
        return "-"
    if s < 1e-3:
        return f"{s * 1e6:.3g} us"
    if s < 1.0:
        return f"{s * 1e3:.3g} ms"
    return f"{s:.3g} s"


def fmt_rate(pixels: float, seconds: float | None) -> str:
    """Pixels per second, scientific (``-`` when not measured)."""
    if not seconds:
        return "-"
    return f"{pixels / seconds:.3g}"


def format_table(headers: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    """A left-aligned plain-text table."""
    cells = [[str(h) for h in headers]] + [[str(c) for c in r] for r in rows]
    widths = [max(len(r[i]) for r in cells) for i in range(len(headers))]
    line = lambda r: "  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip()  # noqa: E731
    return "\n".join([line(cells[0]), line(["-" * w for w in widths])] + [line(r) for r in cells[1:]])


def print_table(title: str, headers: Sequence[str], rows: Sequence[Sequence[Any]]) -> None:
    """Print a titled table followed by a blank line."""
    print(title)
    print(format_table(headers, rows))
    print()
