"""The command line's server (isocsg/cli/server_*.py): the same output as a process of its own.

Judge: the command run in a process of its own (``ISOCSG_SERVER=0``, as every other test runs
it): a command served by the warm process must write the same PNG bytes, the same standard
output and error, and end with the same exit code. The rest is the server's life: started by
a client that found none, refused once isocsg's files change, stopped, killed (the client
runs the command itself), idle.

The servers here run a copy of isocsg in a temporary directory (so that a file can be touched;
it has no numba cache, so the models stay small enough to be drawn without numba, as a new
process draws them), their sockets in a private directory, an idle timeout of 30 s, and are
stopped after each test.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from isocsg.cli.server import stop_servers

pytestmark = pytest.mark.skipif(not hasattr(os, "fork"), reason="the server needs fork (POSIX)")

ROOT = Path(__file__).resolve().parents[1]
MODELS = {
    "cube.scad": "cube(1);\n",
    "difference.scad": "difference() { cube(10, center=true); sphere(6.5); }\n",
    "tree.csg": "group() {\n  union() {\n    cube(size = [2, 2, 2], center = true);\n"
                "    sphere($fn = 0, $fa = 12, $fs = 2, r = 1.3);\n  }\n}\n",
}


@pytest.fixture(scope="module")
def package() -> Iterator[Path]:
    """A copy of isocsg (no caches), in a directory of its own."""
    where = Path(tempfile.mkdtemp(prefix="isocsg-pkg-"))
    shutil.copytree(ROOT / "isocsg", where / "isocsg", ignore=shutil.ignore_patterns("__pycache__"))
    yield where
    shutil.rmtree(where, ignore_errors=True)


def _environment(package: Path) -> dict[str, str]:
    runtime = tempfile.mkdtemp(prefix="isrv-", dir="/tmp")  # short: a socket's path has ~100 bytes
    env = {**os.environ, "ISOCSG_SERVER": "1", "ISOCSG_RUNTIME_DIR": runtime, "ISOCSG_SERVER_IDLE": "30",
           "PYTHONPATH": str(package)}
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env


def _stop_all(env: dict[str, str]) -> None:
    """Stop every server of ``env``'s directory (one a client started just now may take its lock a
    moment later: asked twice), and remove the directory."""
    folder = Path(env["ISOCSG_RUNTIME_DIR"])
    with contextlib.redirect_stdout(io.StringIO()):
        stop_servers(folder)
        time.sleep(0.2)
        stop_servers(folder)
    shutil.rmtree(folder, ignore_errors=True)


@pytest.fixture(scope="module")
def shared(package: Path) -> Iterator[dict[str, str]]:
    """The environment of a client of a server that the module's first tests share."""
    env = _environment(package)
    yield env
    _stop_all(env)


@pytest.fixture
def env(package: Path) -> Iterator[dict[str, str]]:
    """The environment of a client of a private server; every server of it stopped afterwards."""
    env = _environment(package)
    yield env
    _stop_all(env)


def isocsg(env: dict[str, str], *argv: str, cwd: Path | None = None,
           stdin: str | None = None) -> subprocess.CompletedProcess[str]:
    """``python -m isocsg argv`` in a new process (in ``cwd``, else in the copy's directory: a
    checkout's own isocsg in the working directory would come first on ``sys.path``)."""
    try:
        return subprocess.run([sys.executable, "-m", "isocsg", *argv], env=env, cwd=cwd or env["PYTHONPATH"],
                              input=stdin, capture_output=True, text=True, timeout=120)
    except subprocess.TimeoutExpired as exc:
        raise AssertionError(f"isocsg {' '.join(argv)} ran over 120 s; {_logs(env)}") from exc


def _logs(env: dict[str, str]) -> str:
    """The servers' logs of ``env``'s directory and what runs there (for a failure's message)."""
    folder = Path(env["ISOCSG_RUNTIME_DIR"])
    texts = [f"{p.name}: {p.read_text(errors='replace')[-4000:]!r}" for p in sorted(folder.glob("*.log"))]
    ps = subprocess.run(["ps", "-eo", "pid,ppid,stat,etime,time,args"], capture_output=True, text=True).stdout
    return f"files {sorted(p.name for p in folder.iterdir())}; logs: {texts}; processes:\n{ps[-6000:]}"


def start(env: dict[str, str]) -> int:
    """Start the server (waiting until it is warm); its pid."""
    proc = isocsg(env, "server", "start")
    assert proc.returncode == 0, f"{proc.stderr}; {_logs(env)}"
    return int(re.search(r"pid (\d+)", proc.stdout).group(1))


def served(env: dict[str, str]) -> int:
    """How many commands this installation's server has run (-1: no server)."""
    status = isocsg(env, "server", "status").stdout
    found = re.search(r"\(this installation\): pid \d+, up \d+ s, (\d+) commands served", status)
    return int(found.group(1)) if found else -1


def alone(env: dict[str, str]) -> dict[str, str]:
    return {**env, "ISOCSG_SERVER": "0"}


def outcome(proc: subprocess.CompletedProcess[str], png: Path) -> tuple[object, ...]:
    return proc.returncode, proc.stdout, proc.stderr, png.read_bytes() if png.exists() else None


def test_served_commands_give_the_same_bytes_output_and_exit_codes(shared: dict[str, str], tmp_path: Path) -> None:
    env = shared
    for name, text in MODELS.items():
        (tmp_path / name).write_text(text)
    start(env)
    cases = [
        ["render", "cube.scad", "-o", "out.png", "--no-progress"],
        ["render", "tree.csg", "-o", "out.png", "--no-progress"],
        ["demo", "--size", "48x36", "--contours", "6", "-o", "out.png", "--no-progress"],
        ["render", "missing.scad", "-o", "out.png"],
        ["render", "cube.scad", "-o", "out.png", "--size", "0x"],
    ]
    png = tmp_path / "out.png"
    before = served(env)
    for case in cases:
        results = []
        for run_env in (alone(env), env):
            png.unlink(missing_ok=True)
            results.append(outcome(isocsg(run_env, *case, cwd=tmp_path), png))
        assert results[0] == results[1], case
        assert (results[0][3] is not None) == (results[0][0] == 0), case
    assert served(env) == before + len(cases)


def test_standard_input_and_concurrent_clients(shared: dict[str, str], tmp_path: Path) -> None:
    env = shared
    start(env)
    scene = (ROOT / "isocsg" / "data" / "demo.toml").read_text()
    expect = isocsg(alone(env), "render", "-", "-o", "a.png", "--size", "48x36", "--contours", "6", "--no-progress",
                    cwd=tmp_path, stdin=scene)
    assert expect.returncode == 0, expect.stderr
    before = served(env)
    argv = [sys.executable, "-m", "isocsg", "render", "-", "--size", "48x36", "--contours", "6", "--no-progress", "-o"]
    procs = [subprocess.Popen([*argv, f"c{k}.png"], env=env, cwd=tmp_path, stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) for k in range(2)]
    for k, proc in enumerate(procs):
        out, err = proc.communicate(scene, timeout=300)
        assert (proc.returncode, out, err) == (0, f"wrote c{k}.png\n", "")
        assert (tmp_path / f"c{k}.png").read_bytes() == (tmp_path / "a.png").read_bytes()
    assert served(env) == before + 2


def test_the_client_imports_no_numpy(shared: dict[str, str], tmp_path: Path) -> None:
    env = shared
    (tmp_path / "cube.scad").write_text(MODELS["cube.scad"])
    start(env)
    before = served(env)
    code = ("import sys\nfrom isocsg.cli import main\n"
            "sys.argv = ['isocsg', 'render', 'cube.scad', '-o', 'c.png', '--no-progress']\n"
            "code = main()\nprint(code, sorted(m for m in ('numpy', 'numba') if m in sys.modules))\n")
    proc = subprocess.run([sys.executable, "-c", code], env=env, cwd=tmp_path, capture_output=True, text=True,
                          timeout=300)
    assert proc.stdout == "wrote c.png\n0 []\n", proc.stderr
    assert served(env) == before + 1


def test_stop_then_commands_run_alone_and_start_a_server(env: dict[str, str], tmp_path: Path) -> None:
    (tmp_path / "cube.scad").write_text(MODELS["cube.scad"])
    pid = start(env)
    stopped = isocsg(env, "server", "stop")
    assert stopped.stdout.startswith("stopped server") and f"(pid {pid})" in stopped.stdout
    assert served(env) == -1
    assert "no server running" in isocsg(env, "server", "status").stdout
    log = next(Path(env["ISOCSG_RUNTIME_DIR"]).glob("*.log"))
    log.unlink()
    proc = isocsg(env, "render", "cube.scad", "-o", "c.png", "--no-progress", cwd=tmp_path)
    assert (proc.returncode, proc.stdout) == (0, "wrote c.png\n")
    assert log.exists()  # the command started a server (its log is made before it runs)


def test_a_killed_server_is_not_waited_for(env: dict[str, str], tmp_path: Path) -> None:
    (tmp_path / "cube.scad").write_text(MODELS["cube.scad"])
    os.kill(start(env), signal.SIGKILL)
    time.sleep(0.2)
    proc = isocsg(env, "render", "cube.scad", "-o", "k.png", "--no-progress", cwd=tmp_path)
    assert (proc.returncode, proc.stdout, proc.stderr) == (0, "wrote k.png\n", "")
    assert (tmp_path / "k.png").read_bytes().startswith(b"\x89PNG")


def _long_command(env: dict[str, str], cwd: Path) -> subprocess.Popen[str]:
    """A served command that draws for a while, once the server's child runs it."""
    proc = subprocess.Popen([sys.executable, "-m", "isocsg", "demo", "--size", "3000x3000", "-o", "big.png",
                             "--no-progress"], env=env, cwd=cwd, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    _wait_for(env, "1 running")
    time.sleep(0.5)  # the client is past the handshake: it passes signals on
    return proc


def _wait_for(env: dict[str, str], text: str, seconds: float = 60) -> None:
    deadline = time.monotonic() + seconds
    while text not in isocsg(env, "server", "status").stdout:
        assert time.monotonic() < deadline, f"no server status with {text!r}"
        time.sleep(0.05)


def test_signals_to_the_client_reach_the_command(env: dict[str, str], tmp_path: Path) -> None:
    env = {**env, "ISOCSG_JIT": "python"}  # a long command: a large image drawn without numba
    start(env)
    proc = _long_command(env, tmp_path)
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=120)
    assert (proc.returncode, out, err) == (130, "", "isocsg: interrupted\n")
    assert not (tmp_path / "big.png").exists()
    _wait_for(env, " 0 running", 10)
    proc = _long_command(env, tmp_path)
    proc.send_signal(signal.SIGTERM)  # the child ends by it, then the client
    assert proc.wait(timeout=120) == -signal.SIGTERM
    _wait_for(env, " 0 running", 10)
    proc = _long_command(env, tmp_path)
    proc.kill()  # the client cannot pass SIGKILL on: the child sees its socket close
    proc.wait(timeout=120)
    _wait_for(env, " 0 running", 10)


def test_edited_files_are_never_served_by_the_old_server(env: dict[str, str], package: Path, tmp_path: Path) -> None:
    (tmp_path / "cube.scad").write_text(MODELS["cube.scad"])
    pid = start(env)
    before = served(env)
    touched = package / "isocsg" / "cli" / "demo.py"
    os.utime(touched, ns=(time.time_ns(), time.time_ns()))
    proc = isocsg(env, "render", "cube.scad", "-o", "c.png", "--no-progress", cwd=tmp_path)
    assert (proc.returncode, proc.stdout) == (0, "wrote c.png\n")
    assert served(env) in (-1, 0)  # the new files' server, if it answers yet, has served none
    deadline = time.monotonic() + 20  # the old server sees its files changed within seconds
    while _alive(pid) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not _alive(pid)
    assert before >= 0  # the old server answered before the edit


def test_an_idle_server_leaves(env: dict[str, str]) -> None:
    pid = start({**env, "ISOCSG_SERVER_IDLE": "1"})
    deadline = time.monotonic() + 20
    while _alive(pid) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not _alive(pid)
    assert not list(Path(env["ISOCSG_RUNTIME_DIR"]).glob("*.sock"))


def test_disabled_server_is_never_asked_nor_started(env: dict[str, str], tmp_path: Path) -> None:
    (tmp_path / "cube.scad").write_text(MODELS["cube.scad"])
    proc = isocsg(alone(env), "render", "cube.scad", "-o", "c.png", "--no-progress", cwd=tmp_path)
    assert proc.returncode == 0
    assert not list(Path(env["ISOCSG_RUNTIME_DIR"]).iterdir())
    refused = isocsg(alone(env), "server", "start")
    assert refused.returncode == 2 and "disabled" in refused.stderr


def _alive(pid: int) -> bool:
    """Whether ``pid`` runs (a zombie does not: the test's servers are not its children)."""
    try:
        status = Path(f"/proc/{pid}/status").read_text()
    except OSError:
        return False
    return "zombie" not in status.lower()


def test_the_digest_depends_on_values_only() -> None:
    """Equal fingerprints, one with a value shared by two keys (as three ``*_NUM_THREADS=1``
    variables left by dask's nanny are), one with its own copies: one name (marshal's bytes
    differ between them, which made a warmed-up server leave as if its files had changed)."""
    from isocsg.cli.server_protocol import digest, fingerprint

    shared_value = "".join(["4", "2"])
    base = fingerprint({})
    one = [*base[:-1], [("MKL_NUM_THREADS", shared_value), ("OMP_NUM_THREADS", shared_value)]]
    other = [*base[:-1], [("MKL_NUM_THREADS", "".join(["4", "2"])), ("OMP_NUM_THREADS", "".join(["4", "2"]))]]
    assert one == other
    assert digest(one) == digest(other)
    assert digest(one) != digest([*base[:-1], [("MKL_NUM_THREADS", "42"), ("OMP_NUM_THREADS", "43")]])
