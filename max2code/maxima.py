"""One Maxima session: write a script, run it under a timeout and an output cap, scan for errors.

Maxima exits 0 even after errors, asks questions on a closed stdin and then loops printing them,
and wraps long lines; so we run it in a private temporary directory with stdin closed, read its
output from a file whose size we watch, and judge success from the text it printed. Statements
are preceded by `:lisp` markers (which leave Maxima's `%` alone) so that an error can be traced
back to the .mxm statement that raised it.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import tempfile
import time
from dataclasses import dataclass

from . import cache, depfile
from .diagnostics import Pos, error
from .spec import Statement

MARK = "@@M2C"
DEFAULT_TIMEOUT = 120.0
OUTPUT_CAP = 64 * 1024 * 1024

# Each pattern's group 1 is the detail a user needs to see.
_ERRORS = (
    re.compile(r"^(incorrect syntax:.*)$", re.M),
    re.compile(r"^(.*)\n -- an error\.", re.M),
    re.compile(r"^Maxima encountered a Lisp error:\s*(?:Condition in .*?: )?(\S.*)$", re.M),
)
_QUESTION = re.compile(r"^(Is .*\?)\s*$", re.M)
_INSTALL_HINT = ("install it: Debian/Ubuntu 'apt-get install maxima', Fedora 'dnf install maxima', "
                 "macOS 'brew install maxima'; or set MAXIMA to its path")


@dataclass(frozen=True)
class Session:
    """The output of one finished run, with the statement positions for error mapping."""

    output: str
    seconds: float
    cached: bool = False


def maxima_executable(where: Pos | None = None) -> str:
    exe = os.environ.get("MAXIMA") or shutil.which("maxima")
    if not exe:
        raise error(where or Pos("max2code", 1, 1), f"'maxima' not found on PATH; {_INSTALL_HINT}")
    return exe


def marker(tag: str, arg: object = "") -> str:
    """A script line that prints a marker without touching Maxima's `%`."""
    return f':lisp (format t "~%{MARK}-{tag} {arg}~%")\n'


def program_script(statements: tuple[Statement, ...]) -> str:
    """The user's statements, each announced by a marker naming its index."""
    parts = ["display2d:false$\nlinel:1000000$\n", search_path(statements)]
    for index, stmt in enumerate(statements):
        parts.append(marker("STMT", index))
        parts.append(stmt.text + "\n")
    parts.append(marker("PROGRAM-DONE"))
    return "".join(parts)


def search_path(statements: tuple[Statement, ...]) -> str:
    """Let `load("x.mac")` find files beside the .mxm: Maxima runs in a private folder.

    Added only when the program loads something, so other scripts (and their cache keys) do not
    depend on where the .mxm lies.
    """
    folder = depfile.source_folder(statements)
    if folder is None or not any(depfile.ANY_LOAD.search(s.text) for s in statements):
        return ""
    if any(c in folder for c in '{}#"\\'):
        return ""  # would be read as a pattern; such loads need an absolute path
    return (f'file_search_maxima: append(["{folder}/###", "{folder}/###.{{mac,mc,wxm}}"], '
            f'file_search_maxima)$\n'
            f'file_search_lisp: append(["{folder}/###", "{folder}/###.{{lisp,lsp}}"], '
            f'file_search_lisp)$\n')


def run(script: str, statements: tuple[Statement, ...], where: Pos,
        timeout: float = DEFAULT_TIMEOUT) -> Session:
    """Run a script; raise a diagnostic at the offending statement if Maxima reports an error.

    A successful run's output is cached (see cache.py) under a hash of the script, the files it
    loads, Maxima's identity and max2code's version; a hit skips Maxima altogether.
    """
    exe = maxima_executable(where)
    key = cache.key(script, exe, depfile.loaded_files(statements))
    hit = cache.get(key)
    if hit is not None:
        _check(hit.output, statements, where, None, timeout)
        return Session(hit.output, hit.seconds, cached=True)
    with tempfile.TemporaryDirectory(prefix="max2code-") as tmp:
        path = os.path.join(tmp, "job.mac")
        with open(path, "w", encoding="utf-8") as f:
            f.write(script)
        out_path = os.path.join(tmp, "out.txt")
        start = time.monotonic()
        with open(out_path, "wb") as out:
            try:
                proc = subprocess.Popen(
                    [exe, "--very-quiet", "-b", path],
                    stdin=subprocess.DEVNULL, stdout=out, stderr=subprocess.STDOUT, cwd=tmp,
                    start_new_session=True, env={**os.environ, "HOME": tmp},
                )
            except OSError as exc:
                raise error(where, f"cannot run Maxima ({exe}): {exc.strerror}; {_INSTALL_HINT}") from None
            reason = _wait(proc, out_path, timeout)
            status = proc.returncode
        seconds = time.monotonic() - start
        with open(out_path, "rb") as f:
            text = f.read(OUTPUT_CAP).decode("utf-8", errors="replace")
    _check(text, statements, where, reason, timeout)
    if reason is None and status == 0 and _reached_end(script, text):
        cache.put(key, cache.Entry(text, seconds))
    return Session(text, seconds)


def _reached_end(script: str, text: str) -> bool:
    """Whether the run printed the script's last marker: it ran to the end, so it may be cached."""
    tags = re.findall(rf"{MARK}-([A-Z0-9-]+)", script)
    return not tags or re.search(rf"^{MARK}-{re.escape(tags[-1])}\b", text, re.M) is not None


def _wait(proc: subprocess.Popen[bytes], out_path: str, timeout: float) -> str | None:
    """Wait for Maxima; kill its whole process group on timeout or runaway output."""
    deadline = time.monotonic() + timeout
    delay = 0.005
    while proc.poll() is None:
        reason = None
        if time.monotonic() > deadline:
            reason = "timeout"
        elif os.path.getsize(out_path) > OUTPUT_CAP:
            reason = "output"
        if reason:
            try:
                os.killpg(proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            proc.wait()
            return reason
        time.sleep(delay)
        delay = min(delay * 2, 0.05)
    return None


def statement_at(text: str, statements: tuple[Statement, ...], where: Pos, offset: int) -> Pos:
    """The position of the last statement whose marker precedes `offset` in the output."""
    found = None
    for m in re.finditer(rf"^{MARK}-STMT (\d+)$", text[:offset], re.M):
        found = int(m.group(1))
    if found is None or found >= len(statements):
        return where
    return statements[found].pos


def _check(text: str, statements: tuple[Statement, ...], where: Pos, reason: str | None,
           timeout: float) -> None:
    question = _QUESTION.search(text)
    if question:
        pos = statement_at(text, statements, where, question.start())
        raise error(pos, f"Maxima asked a question it cannot be answered here: "
                    f"'{question.group(1).strip()}' (declare the sign with assume(), e.g. "
                    f"assume(n > 0))")
    for pattern in _ERRORS:
        m = pattern.search(text)
        if m:
            pos = statement_at(text, statements, where, m.start())
            detail = m.group(1).strip() or "(no message)"
            raise error(pos, f"Maxima error: {detail}")
    if reason == "timeout":
        pos = statement_at(text, statements, where, len(text))
        raise error(pos, f"Maxima did not finish within {timeout:g} s (raise it with --timeout)")
    if reason == "output":
        pos = statement_at(text, statements, where, len(text))
        raise error(pos, f"Maxima printed more than {OUTPUT_CAP // (1024 * 1024)} MiB; stopped")
