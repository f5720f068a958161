"""An interrupted max2code leaves no Maxima behind, and no private folder.

Each test starts max2code on a program that would run for hours (`for i: 1 thru 10^12`), waits
until its Maxima is running, then kills max2code: with SIGTERM, SIGINT and SIGHUP it must exit
143, 130 and 129, with SIGKILL the kernel must take Maxima with it; the same for `build -j 2`
with two Maxima runs at once. Every run has a TMPDIR of its own, so "no max2code-* folder
left" is checked without looking at other programs' files.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import ROOT

LOOP = ROOT / "tests" / "bad" / "maxima-timeout.mxm"
WAIT = 60.0


def children_of(pid: int) -> list[int]:
    out = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                stat = Path(f"/proc/{entry}/stat").read_text()
            except OSError:
                continue
            fields = stat[stat.rindex(")") + 2:].split()
            if int(fields[1]) == pid and fields[0] != "Z":
                out.append(int(entry))
    return out


def alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return state[state.rindex(")") + 2] != "Z"


def start(args: list[str], tmp: Path) -> subprocess.Popen[str]:
    tmpdir = tmp / "tmpdir"
    tmpdir.mkdir(exist_ok=True)
    env = {**os.environ, "TMPDIR": str(tmpdir), "MAX2CODE_CACHE": str(tmp / "cache")}
    return subprocess.Popen([sys.executable, "-m", "max2code", *args], cwd=ROOT, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def wait_for_maxima(proc: subprocess.Popen[str], count: int, tmp: Path) -> list[int]:
    """The Maxima processes once `count` of them run and have opened their scripts (their
    private folders are gone by then)."""
    deadline = time.monotonic() + WAIT
    while time.monotonic() < deadline:
        assert proc.poll() is None, proc.communicate()
        pids = children_of(proc.pid)
        folders = list((tmp / "tmpdir").glob("max2code-*"))
        if len(pids) == count and not folders:
            time.sleep(0.3)  # well into the loop
            return pids
        time.sleep(0.05)
    raise AssertionError(f"no {count} Maxima processes started")


def gone(pids: list[int]) -> bool:
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:
        if not any(alive(p) for p in pids):
            return True
        time.sleep(0.05)
    return False


def stop(pids: list[int]) -> None:
    for pid in pids:  # never leave a process behind, even when the test fails
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass


SIGNALS = [(signal.SIGTERM, 143), (signal.SIGINT, 130), (signal.SIGHUP, 129), (signal.SIGKILL, -9)]


@pytest.mark.parametrize("signum,status", SIGNALS, ids=lambda v: getattr(v, "name", str(v)))
def test_killed_max2code_leaves_nothing(signum: int, status: int, tmp_path: Path,
                                        maxima_exe: str) -> None:
    out = tmp_path / "out.h"
    proc = start(["--lang=c", str(LOOP), "-o", str(out), "--timeout", "600"], tmp_path)
    pids = []
    try:
        pids = wait_for_maxima(proc, 1, tmp_path)
        proc.send_signal(signum)
        proc.wait(timeout=30)
        assert proc.returncode == status, proc.stderr.read() if proc.stderr else ""
        assert gone(pids), f"Maxima {pids} outlived max2code ({signal.Signals(signum).name})"
        assert list((tmp_path / "tmpdir").iterdir()) == []
        assert not out.exists()
        if signum != signal.SIGKILL:
            assert "Traceback" not in proc.stderr.read()  # type: ignore[union-attr]
    finally:
        stop(pids)
        proc.kill()
        proc.wait()


@pytest.mark.parametrize("signum,status", [SIGNALS[0], SIGNALS[3]],
                         ids=lambda v: getattr(v, "name", str(v)))
def test_killed_build_jobs_leave_nothing(signum: int, status: int, tmp_path: Path,
                                         maxima_exe: str) -> None:
    sources = []
    for k in range(3):  # two run at once, the third must never start
        path = tmp_path / f"loop{k}.mxm"
        path.write_text(LOOP.read_text().replace("s: 0$", f"s: {k}$"))
        sources.append(str(path))
    proc = start(["build", "-j", "2", "-o", str(tmp_path / "build"), "--timeout", "600", *sources],
                 tmp_path)
    pids = []
    try:
        pids = wait_for_maxima(proc, 2, tmp_path)
        proc.send_signal(signum)
        proc.wait(timeout=30)
        assert proc.returncode == status
        assert gone(pids), f"Maxima {pids} outlived 'max2code build -j 2'"
        assert list((tmp_path / "tmpdir").iterdir()) == []
        assert not (tmp_path / "build" / "summary.md").exists()
    finally:
        stop(pids)
        proc.kill()
        proc.wait()


def test_folders_of_dead_runs_are_swept(tmp_path: Path, maxima_exe: str) -> None:
    """A folder left by a max2code killed during Maxima's first moments goes at the next run;
    one whose max2code still lives (here: this test's own process) stays."""
    tmpdir = tmp_path / "tmpdir"
    tmpdir.mkdir()
    dead = subprocess.Popen(["true"])
    dead.wait()
    stale = tmpdir / f"max2code-{dead.pid}-abc123"
    stale.mkdir()
    (stale / "job.mac").write_text("x;\n")
    living = tmpdir / f"max2code-{os.getpid()}-def456"
    living.mkdir()
    proc = start(["--lang=python", str(ROOT / "equations" / "point-line.mxm"), "-o",
                  str(tmp_path / "out.py"), "--no-cache"], tmp_path)
    proc.communicate(timeout=120)
    assert proc.returncode == 0
    assert not stale.exists()
    assert living.exists()
    shutil.rmtree(living)
