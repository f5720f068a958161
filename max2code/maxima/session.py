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

from .. import cache
from . import children, confine, depfile, lockdown, names as maxima_names
from ..diagnostics import Pos, error
from .text import advance
from ..front.spec import Statement

MARK = "@@M2C"
DEFAULT_TIMEOUT = 120.0
OUTPUT_CAP = 64 * 1024 * 1024

# Each pattern's group 1 is the detail a user needs to see.
_ERRORS = (
    re.compile(r"^(incorrect syntax:.*)$", re.M),
    re.compile(r"^(.*)\n -- an error\.", re.M),
    re.compile(r"^Maxima encountered a Lisp error:\s*(?:Condition in .*?: )?(\S.*)$", re.M),
    re.compile(r"^(Unrecoverable error: .*)$", re.M),  # GCL itself gave up (out of memory, ...)
)
# GCL's words when its heap is full (the memory limit, or GCL_MEM_MULTIPLE of it, reached).
_EXHAUSTED = re.compile(r"storage for \S+ is exhausted")
_REFUSED = re.compile(rf"^{MARK}-REFUSED (.*)$", re.M)
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


def program_script(statements: tuple[Statement, ...], names: frozenset[str] = frozenset(),
                   renamed: bool = False) -> str:
    """The user's statements, each announced by a marker naming its index; unless unsafe
    Maxima is allowed, checked first and preceded by the lock-down (lockdown.py); `names` are
    the .mxm's own (declared) names, symbols even when Maxima has a function of that name.
    `renamed`: the oracle's copy, whose parameters it renamed to its own o__ names (the
    user's program was checked before)."""
    if not renamed:
        _no_own_names(statements)
    parts = ["display2d:false$\nlinel:1000000$\n", search_path(statements)]
    if not _policy.allow_unsafe:
        parts.append(lockdown.prelude(lockdown.check(statements, names), f"~%{MARK}-"))
    if not renamed:  # (after the lock-down's refusals, which matter more)
        maxima_names.check_program(statements)
    for index, stmt in enumerate(statements):
        parts.append(marker("STMT", index))
        parts.append(stmt.text + "\n")
    parts.append(marker("PROGRAM-DONE"))
    return "".join(parts)


# The prefixes of the names max2code's own Maxima code uses (the coefficients' extraction,
# m2c__; the oracle, o__). Maxima's variables are dynamically scoped: a user's symbol of one
# of those names would be bound by that code's loops (a parameter m2c__k read as the loop's
# index made x + m2c__k t "not a polynomial"; o__e made the oracle's vectors vanish).
_OWN = re.compile(r"(?<![\w%])(?:m2c__|o__)\w*", re.I)


def _no_own_names(statements: tuple[Statement, ...]) -> None:
    """A name the user's program shares with max2code's Maxima code is an error, located."""
    for stmt in statements:
        m = _OWN.search(stmt.text)
        if m:
            raise error(advance(stmt.pos, stmt.text[:m.start()]),
                        f"'{m.group()}': names beginning with m2c__ or o__ are max2code's own in "
                        f"Maxima (its variables there would take the name's place); rename it")


def search_path(statements: tuple[Statement, ...]) -> str:
    """Let `load("x.mac")` find files beside the .mxm: Maxima runs in a private folder.

    Added only when the program loads something, so other scripts (and their cache keys) do not
    depend on where the .mxm lies.
    """
    folder = depfile.source_folder(statements)
    if folder is None or not any(depfile.ANY_LOAD.search(s.text) for s in statements):
        return ""
    if any(c in folder for c in '{}#",[]*?\\'):
        return ""  # would be read as a pattern; such loads need an absolute path (README)
    return (f'file_search_maxima: append(["{folder}/###", "{folder}/###.{{mac,mc,wxm}}"], '
            f'file_search_maxima)$\n'
            f'file_search_lisp: append(["{folder}/###", "{folder}/###.{{lisp,lsp}}"], '
            f'file_search_lisp)$\n')


@dataclass(frozen=True)
class Policy:
    """How Maxima runs in this process: the CLI sets it once (`configure`)."""

    memory_mib: int = confine.DEFAULT_MEMORY_MIB
    allow_unsafe: bool = False


_policy = Policy()


def configure(memory_mib: int | None = None, allow_unsafe: bool | None = None) -> None:
    """Set the memory limit (MiB, 0 for none) and whether the lock-down is lifted."""
    global _policy
    if memory_mib is not None and 0 < memory_mib < confine.MIN_MEMORY_MIB:
        raise error(Pos("max2code", 1, 1), f"a Maxima memory limit of {memory_mib} MiB is below "
                    f"the {confine.MIN_MEMORY_MIB} MiB GCL needs to start")
    _policy = Policy(_policy.memory_mib if memory_mib is None else memory_mib,
                     _policy.allow_unsafe if allow_unsafe is None else allow_unsafe)


def policy() -> Policy:
    return _policy


def run(script: str, statements: tuple[Statement, ...], where: Pos,
        timeout: float = DEFAULT_TIMEOUT) -> Session:
    """Run a script; raise a diagnostic at the offending statement if Maxima reports an error.

    A successful run's output is cached (see cache.py) under a hash of the script, the files it
    loads, Maxima's identity and max2code's version; a hit skips Maxima altogether. A run whose
    loads cannot all be named (a computed file name, allowed only with --allow-unsafe-maxima)
    is never cached: its inputs are unknown.
    """
    exe = maxima_executable(where)
    loads = depfile.loaded_files(statements)
    cacheable = depfile.all_loads_literal(statements)
    key = cache.key(script, exe, loads)
    hit = cache.get(key) if cacheable else None
    if hit is not None:
        _check(hit.output, statements, where, None, timeout)
        return Session(hit.output, hit.seconds, cached=True)
    text, seconds, reason = _execute(exe, script, where, timeout, loads)
    _check(text, statements, where, reason, timeout)
    if reason is None and _reached_end(script, text) and cacheable:
        cache.put(key, cache.Entry(text, seconds))
    return Session(text, seconds)


def _execute(exe: str, script: str, where: Pos, timeout: float,
             loads: tuple[str, ...]) -> tuple[str, float, str | None]:
    """Run Maxima once, confined (confine.py), in a private folder that is removed as soon as
    Maxima has opened its script; return its output, the time taken and why it was stopped."""
    private = children.private_folder()
    try:
        path = os.path.join(private, "job.mac")
        with open(path, "w", encoding="utf-8") as f:
            f.write(STARTED + script)
        limits = confine.Limits(timeout, _policy.memory_mib)
        readable = (private, *_installation(exe), *(os.path.abspath(p) for p in loads))
        with tempfile.TemporaryFile(dir=private) as out:
            start = time.monotonic()
            try:
                proc = children.spawn(
                    [exe, "--very-quiet", "-b", path], cwd=private, stdout=out,
                    env=confine.environment(private),
                    preexec=confine.preexec(limits, readable, not _policy.allow_unsafe))
            except OSError as exc:
                raise error(where, f"cannot run Maxima ({exe}): {exc.strerror}; {_INSTALL_HINT}") from None
            try:
                reason = _wait(proc, out.fileno(), timeout, private)
            finally:
                children.finish(proc)
            seconds = time.monotonic() - start
            if reason is None and proc.returncode < 0:
                reason = f"signal {-proc.returncode}"
            out.seek(0)
            text = out.read(OUTPUT_CAP).decode("utf-8", errors="replace")
    finally:
        shutil.rmtree(private, ignore_errors=True)
    return text, seconds, reason


# The first line of every script: once Maxima has printed it, it has the script open and the
# private folder can go (an open file outlives its name), so even SIGKILL leaves nothing behind.
STARTED = f':lisp (format t "~%{MARK}-STARTED~%")\n'


def _installation(exe: str) -> tuple[str, ...]:
    """Maxima's installation prefix (/usr for Debian's), readable by the confined process."""
    prefix = os.path.dirname(os.path.dirname(os.path.realpath(exe)))
    return (prefix,) if prefix not in ("/", "") else ()


def _reached_end(script: str, text: str) -> bool:
    """Whether the run printed the script's last marker: it ran to the end, so it may be cached."""
    tags = re.findall(rf"{MARK}-([A-Z0-9-]+)", script)
    return not tags or re.search(rf"^{MARK}-{re.escape(tags[-1])}\b", text, re.M) is not None


def _wait(proc: subprocess.Popen[bytes], out: int, timeout: float, private: str) -> str | None:
    """Wait for Maxima; stop it on timeout or runaway output; drop the private folder once the
    script is open."""
    deadline = time.monotonic() + timeout
    delay = 0.005
    started = False
    while proc.poll() is None:
        reason = None
        if time.monotonic() > deadline:
            reason = "timeout"
        elif os.fstat(out).st_size > OUTPUT_CAP:
            reason = "output"
        if reason:
            children.finish(proc)
            return reason
        if not started and f"{MARK}-STARTED".encode() in os.pread(out, 4096, 0):
            started = True
            shutil.rmtree(private, ignore_errors=True)
        time.sleep(delay)
        delay = min(delay * 2, 0.05)
    return None


def _memory_hint() -> str:
    limit = _policy.memory_mib
    return (f"; Maxima may use {limit} MiB of memory: raise it with --maxima-memory"
            if limit else "")


def statement_at(text: str, statements: tuple[Statement, ...], where: Pos, offset: int) -> Pos:
    """The position of the last statement whose marker precedes `offset` in the output."""
    stmt = _statement_before(text, statements, offset)
    return where if stmt is None else stmt.pos


def _statement_before(text: str, statements: tuple[Statement, ...], offset: int) -> Statement | None:
    found = None
    for m in re.finditer(rf"^{MARK}-STMT (\d+)$", text[:offset], re.M):
        found = int(m.group(1))
    return None if found is None or found >= len(statements) else statements[found]


_SHOWN = re.compile(r"Space|Tab|\\([0-7]{3})|(.)", re.S)


def syntax_error_pos(stmt: Statement, shown: str, caret: str) -> Pos:
    """Where in the .mxm Maxima's syntax error points. Maxima prints the line it was reading
    (from the statement's start on its first line), spaces as `Space`, tabs as `Tab`, other
    bytes above 127 as octal escapes, and under it a caret at a byte offset into that line.
    The line is found among the statement's lines by that text; the statement's own position
    is the answer when it cannot be."""
    if not caret.strip() == "^":
        return stmt.pos
    pattern = "".join(
        "[ ]" if m.group() == "Space" else "\t" if m.group() == "Tab"
        else re.escape(bytes([int(m.group(1), 8)]).decode("latin-1")) if m.group(1)
        else re.escape(m.group(2))
        for m in _SHOWN.finditer(shown))
    offset = len(caret) - 1
    for number, line in enumerate(stmt.text.split("\n")):
        raw = line.encode("utf-8", "replace").decode("latin-1")  # bytes, as Maxima counts them
        if re.match(pattern, raw) and offset <= len(raw):
            column = len(raw[:offset].encode("latin-1").decode("utf-8", "ignore"))
            if number == 0:
                return Pos(stmt.pos.file, stmt.pos.line, stmt.pos.col + column)
            return Pos(stmt.pos.file, stmt.pos.line + number, column + 1)
    return stmt.pos


def _check(text: str, statements: tuple[Statement, ...], where: Pos, reason: str | None,
           timeout: float) -> None:
    refused = _REFUSED.search(text)
    if refused:
        pos = statement_at(text, statements, where, refused.start())
        what = refused.group(1).strip()
        raise error(pos, f"the program reached '{what}' at run time, which {lockdown.why(what)}; "
                    f"not allowed in a .mxm ({lockdown.LIFTED})")
    question = _QUESTION.search(text)
    if question:
        pos = statement_at(text, statements, where, question.start())
        raise error(pos, f"Maxima asked a question it cannot be answered here: "
                    f"'{question.group(1).strip()}' (declare the sign with assume(), e.g. "
                    f"assume(n > 0))")
    exhausted = _EXHAUSTED.search(text)
    if exhausted:
        pos = statement_at(text, statements, where, exhausted.start())
        raise error(pos, f"Maxima ran out of memory ({exhausted.group(0)})" + _memory_hint())
    for pattern in _ERRORS:
        m = pattern.search(text)
        if m:
            pos = statement_at(text, statements, where, m.start())
            stmt = _statement_before(text, statements, m.start())
            if pattern is _ERRORS[0] and stmt is not None:  # incorrect syntax: the caret's column
                shown, _, caret = text[m.end() + 1:].partition("\n")
                pos = syntax_error_pos(stmt, shown, caret.split("\n")[0])
            detail = m.group(1).strip() or "(no message)"
            raise error(pos, f"Maxima error: {detail}")
    if reason == "timeout":
        pos = statement_at(text, statements, where, len(text))
        raise error(pos, f"Maxima did not finish within {timeout:g} s (raise it with --timeout)")
    if reason == "output":
        pos = statement_at(text, statements, where, len(text))
        raise error(pos, f"Maxima printed more than {OUTPUT_CAP // (1024 * 1024)} MiB; stopped")
    if reason is not None and reason.startswith("signal"):
        pos = statement_at(text, statements, where, len(text))
        signum = int(reason.split()[1])
        if signum == signal.SIGXCPU:
            raise error(pos, f"Maxima used more than {int(timeout) + confine.CPU_GRACE_SECONDS} s "
                        f"of CPU time; stopped (raise it with --timeout)")
        raise error(pos, f"Maxima was killed by {signal.Signals(signum).name}"
                    + _memory_hint())
