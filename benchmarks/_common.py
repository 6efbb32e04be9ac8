"""Shared helpers of the benchmark scripts: median timing and plain-text tables."""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable, Sequence
from typing import Any

__all__ = ["median_time", "format_table", "print_table", "fmt_seconds", "fmt_rate", "run_child", "openscad_export"]


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


def run_child(argv: Sequence[str], timeout: float, *, env: dict[str, str] | None = None,
              poll: float = 0.1, max_rss_mb: float | None = None) -> tuple[list[dict[str, Any]], str, float]:
    """Run ``argv`` in a fresh process that prints one JSON object per line; stop it after ``timeout`` s
    (or once its resident set passes ``max_rss_mb``).

    Returns the objects read, a status (``"ok"``, ``"timeout"``, ``"over N MB"`` or
    ``"exit N"`` with the last line of its stderr) and the peak resident set of the
    process and its child processes together (isocsg's helper process of background
    Booleans) in MB, polled with psutil while it runs (each object may also report the
    child's own peak).
    """
    import json
    import subprocess
    import tempfile

    import psutil

    with tempfile.TemporaryFile(mode="w+") as out, tempfile.TemporaryFile(mode="w+") as err:
        proc = subprocess.Popen(list(argv), stdout=out, stderr=err, env=env, text=True)
        ps = psutil.Process(proc.pid)
        peak = 0.0
        t0 = time.perf_counter()
        status = "ok"
        while proc.poll() is None:
            try:  # the process and its own (isocsg's helper process of background Booleans), at once
                rss = ps.memory_info().rss
                for child in ps.children(recursive=True):
                    try:
                        rss += child.memory_info().rss
                    except psutil.Error:
                        pass
                peak = max(peak, rss / 2**20)
            except psutil.Error:
                pass
            if time.perf_counter() - t0 > timeout:
                status = "timeout"
            elif max_rss_mb is not None and peak > max_rss_mb:
                status = f"over {max_rss_mb:.0f} MB"
            if status != "ok":
                proc.kill()
                proc.wait()
                break
            time.sleep(poll)
        if status == "ok" and proc.returncode != 0:
            err.seek(0)
            lines = [ln for ln in err.read().splitlines() if ln.strip()]
            status = f"exit {proc.returncode}: {lines[-1][:160] if lines else ''}"
        out.seek(0)
        records = []
        for line in out.read().splitlines():
            try:
                records.append(json.loads(line))
            except ValueError:
                continue
    peak = max([peak] + [float(r.get("maxrss_mb", 0.0)) for r in records])
    return records, status, peak


def openscad_export(model: Any, out: Any, timeout: float) -> bool:
    """``openscad -o OUT MODEL`` (run in the model's folder) unless ``out`` exists; whether ``out``
    exists afterwards (False when the program timed out or wrote nothing)."""
    import subprocess

    if not out.exists():
        try:
            subprocess.run(["openscad", "-o", str(out), model.name], cwd=model.parent, capture_output=True,
                           timeout=timeout, check=False)
        except subprocess.TimeoutExpired:
            return False
    return bool(out.exists())
