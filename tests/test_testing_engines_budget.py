"""benchmarks/engines.py's time budgets: an engine that crashes or hangs is a finding about that
engine, recorded for the tree, while the reference and the other engines are still judged; a
crash is seen at once (not at the end of the timeout)."""

from __future__ import annotations

import os
import signal
import sys
import time
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import pytest

from isocsg import Box, Union

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "benchmarks"))
import engines  # noqa: E402


def _segfault() -> Any:
    os.kill(os.getpid(), signal.SIGSEGV)


def _hang() -> Any:
    time.sleep(600)


def test_a_crashed_engine_is_seen_at_once():
    t0 = time.time()
    with pytest.raises(engines.EngineCrash, match="exit code"):
        engines.isolated(_segfault, timeout=300)
    assert time.time() - t0 < 100  # the old wait held its own end of the pipe and waited the 300 s


def test_a_hung_engine_is_over_its_budget():
    t0 = time.time()
    with pytest.raises(engines.EngineOverBudget, match="hung over 1 s"):
        engines.isolated(_hang, timeout=1)
    assert time.time() - t0 < 20


def _args(**kw: Any) -> SimpleNamespace:
    base = dict(budget=60, engine_budget=1, tol=1e-3, segments=8, samples=100)
    base.update(kw)
    return SimpleNamespace(**base)


def test_one_engine_over_its_budget_leaves_the_others_judged(monkeypatch):
    real = engines.engine_mesh

    def mesh(eng: str, tree: Any, mf: list[Any], timeout: float = 120.0) -> Any:
        if eng == "slow":
            time.sleep(600)  # in process: stopped by the engine's own SIGALRM
        return real("manifold3d", tree, mf, timeout)

    monkeypatch.setattr(engines, "engine_mesh", mesh)
    tree = Union(Box((0, 0, 0), (1, 1, 1)), Box((0.5, 0.5, 0.5), (1, 1, 1)))
    t0 = time.time()
    rec, notes = engines.judge_tree(3, tree, _args(), ["slow", "manifold3d"])
    assert time.time() - t0 < 40
    assert rec["engines"]["slow"]["status"] == "over budget"
    assert rec["engines"]["manifold3d"]["status"] == "ok"
    assert rec["isocsg_seconds"] < 60
    assert any("slow: over its budget" in n for n in notes)


def test_isocsg_over_the_tree_budget_raises():
    tree = Union(Box((0, 0, 0), (1, 1, 1)), Box((0.5, 0.5, 0.5), (1, 1, 1)))
    with pytest.raises(TimeoutError):
        engines.judge_tree(0, tree, _args(budget=1e-9), ["manifold3d"])
    assert signal.getitimer(signal.ITIMER_REAL)[0] == 0.0  # no alarm left running
