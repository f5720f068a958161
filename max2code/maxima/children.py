"""The Maxima processes this max2code started, and how they end with it.

An interrupted build must not leave Maxima running (it runs in a session of its own, so a
terminal's Ctrl-C does not reach it, and when max2code dies it would be adopted by init and
go on burning a core). So:

* every Maxima process group and private folder is registered while it lives;
* SIGTERM, SIGINT and SIGHUP kill every registered group, then unwind the main thread with
  `Interrupted`: folders are removed on the way out and the CLI exits 128 + the signal
  (143, 130, 129). No new Maxima starts once a signal has arrived (`build -j` workers);
* SIGKILL cannot be caught: the kernel kills Maxima then (PR_SET_PDEATHSIG, see confine.py),
  and a private folder is removed as soon as Maxima has opened its script (session.py), so only
  one killed in its first tenth of a second is left behind; the next run removes those whose
  max2code is gone (`sweep`).
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import stat
import subprocess
import tempfile
import threading
from typing import Any, Callable

PREFIX = "max2code-"
_SIGNALS = (signal.SIGTERM, signal.SIGINT, signal.SIGHUP)

_live: dict[int, subprocess.Popen[bytes]] = {}
_stopping: list[int] = []  # the signal that stops us, once one has arrived
_lock = threading.Lock()


class Interrupted(Exception):
    """A termination signal arrived; the CLI exits with 128 + `signum`."""

    def __init__(self, signum: int) -> None:
        super().__init__(f"interrupted by {signal.Signals(signum).name}")
        self.signum = signum


def install_signal_handlers() -> None:
    """Called once by the CLI, in the main thread."""
    for signum in _SIGNALS:
        signal.signal(signum, _on_signal)


def _on_signal(signum: int, frame: Any) -> None:
    first = not _stopping
    _stopping.append(signum)
    kill_all()
    if first:
        raise Interrupted(signum)


def stopping() -> int | None:
    return _stopping[0] if _stopping else None


def check_running() -> None:
    """Raise `Interrupted` when a signal has arrived: nothing new is started then."""
    if _stopping:
        raise Interrupted(_stopping[0])


def kill_all() -> None:
    """SIGKILL every registered process group (runs in a signal handler: no lock taken)."""
    for proc in list(_live.values()):
        _kill_group(proc)


def _kill_group(proc: subprocess.Popen[bytes]) -> None:
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def spawn(argv: list[str], *, cwd: str, stdout: Any, env: dict[str, str],
          preexec: Callable[[], None]) -> subprocess.Popen[bytes]:
    """Start a process in a new session and register it; raise `Interrupted` (after killing it)
    if a signal arrived meanwhile."""
    check_running()
    with _lock:
        proc = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=stdout,
                                stderr=subprocess.STDOUT, cwd=cwd, env=env,
                                start_new_session=True, preexec_fn=preexec)
        _live[proc.pid] = proc
    if _stopping:  # the handler's snapshot may have missed it
        _kill_group(proc)
    return proc


def finish(proc: subprocess.Popen[bytes]) -> None:
    """Kill what is left of the process group, reap it, and forget it."""
    _kill_group(proc)
    proc.wait()
    with _lock:
        _live.pop(proc.pid, None)


def private_folder() -> str:
    """A new private folder, named for this process so that `sweep` can tell whose it is."""
    sweep()
    return tempfile.mkdtemp(prefix=f"{PREFIX}{os.getpid()}-")


_swept = False


def sweep() -> None:
    """Remove the private folders of max2code processes that no longer exist (killed by SIGKILL
    before they could clean up). Only ours (same user) and only once per process."""
    global _swept
    if _swept:
        return
    _swept = True
    folder = tempfile.gettempdir()
    pattern = re.compile(rf"^{re.escape(PREFIX)}(\d+)-\w+$")
    try:
        names = os.listdir(folder)
    except OSError:
        return
    for name in names:
        m = pattern.match(name)
        if not m or int(m.group(1)) == os.getpid():
            continue
        path = os.path.join(folder, name)
        try:
            info = os.lstat(path)
            if info.st_uid != os.getuid() or not stat.S_ISDIR(info.st_mode):
                continue
            os.kill(int(m.group(1)), 0)
        except ProcessLookupError:
            shutil.rmtree(path, ignore_errors=True)
        except OSError:
            continue
