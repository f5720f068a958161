"""Writing outputs the way build systems like: atomically, and only when the content changes.

Only a regular file is compared and replaced. `-o` may also name a device (`/dev/null`), a FIFO
or a symlink: replacing any of those would be wrong (run as root, the old code replaced the
system's /dev/null with a regular file; reading /dev/full to compare never ended), so something
that is not a regular file is written straight into, never read; a FIFO nobody reads is an
error instead of a wait; and a symlink is followed, the file it points to being the output.
/dev/stdout, /dev/stderr, /dev/fd/N and /proc/self/fd/N are written through that descriptor.
"""

from __future__ import annotations

import errno
import fcntl
import os
import stat
import sys
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from collections.abc import Iterator
from contextlib import contextmanager

from .diagnostics import Pos, error


def write_if_changed(path: str, text: str) -> bool:
    """Write via a temporary file and rename, so a failure never leaves half a file behind.

    An unchanged file keeps its timestamp, so Make and Ninja do not rebuild what depends on it.
    Returns True if the file was (re)written. `-` means standard output.
    """
    if path == "-":
        sys.stdout.write(text)
        sys.stdout.flush()
        return True
    data = text.encode("utf-8", "surrogateescape")
    fd = _descriptor(path)
    if fd is not None:
        _write_fd(path, fd, data)
        return True
    target = os.path.realpath(path)  # a symlink's target is the output; the link stays
    try:
        info = os.stat(target)
    except FileNotFoundError:
        info = None
    except OSError as exc:
        raise error(Pos(path, 1, 1), f"cannot write output: {exc.strerror}") from None
    if info is not None and stat.S_ISDIR(info.st_mode):
        raise error(Pos(path, 1, 1), "cannot write output: it is a directory")
    if info is not None and not stat.S_ISREG(info.st_mode):
        _write_into(path, target, data)
        return True
    if info is not None and info.st_size == len(data) and holds(target, data):
        return False
    _replace(path, target, data)
    return True


def require_folder(path: str) -> None:
    """Refuse at once an output whose folder does not exist (or is not a folder), before any
    slow step runs: `max2code -o missing/x.h` fails in a moment, not after Maxima did its work,
    and like a compiler it does not create the folder (a typo would otherwise scatter files)."""
    if _descriptor(path) is not None:
        return
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        what = "is not a folder" if os.path.exists(folder) else "does not exist"
        raise error(Pos(path, 1, 1), f"cannot write output: its folder {os.path.dirname(path) or '.'!r} {what}")


def _descriptor(path: str) -> int | None:
    """The open descriptor a path names -- /dev/stdout, /dev/stderr, /dev/fd/N,
    /proc/self/fd/N -- or None.  Such an output is written through the descriptor itself,
    whatever it is (a pipe, a terminal, the file a shell redirected to): realpath would name a
    pipe by a path that does not exist, a rename would cut the redirection off from what the
    process prints next, and opening the path anew would write from offset 0 over it."""
    p = os.path.abspath(path)
    named = {"/dev/stdout": 1, "/dev/stderr": 2}
    if p in named:
        return named[p]
    for prefix in ("/dev/fd/", "/proc/self/fd/"):
        if p.startswith(prefix) and p[len(prefix):].isdigit():
            return int(p[len(prefix):])
    return None


def _write_fd(path: str, fd: int, data: bytes) -> None:
    for stream in (sys.stdout, sys.stderr):
        try:
            if stream is not None and stream.fileno() == fd:
                stream.flush()  # what the process printed before comes first
        except (OSError, ValueError):
            pass
    try:
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view):]
    except OSError as exc:
        raise error(Pos(path, 1, 1), f"cannot write output: {exc.strerror}") from None


def holds(path: str, data: bytes) -> bool:
    """Whether a regular file holds exactly `data`, reading at most one byte more."""
    try:
        with open(path, "rb") as f:
            return f.read(len(data) + 1) == data
    except OSError:
        return False


def _write_into(path: str, target: str, data: bytes) -> None:
    """A device or a FIFO: write into it as it is. A FIFO without a reader would block the
    open forever, so it is opened without waiting and refused."""
    try:
        fd = os.open(target, os.O_WRONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    except OSError as exc:
        if exc.errno == errno.ENXIO:
            raise error(Pos(path, 1, 1), "cannot write output: it is a FIFO that no process is "
                        "reading") from None
        raise error(Pos(path, 1, 1), f"cannot write output: {exc.strerror}") from None
    try:
        fcntl.fcntl(fd, fcntl.F_SETFL, fcntl.fcntl(fd, fcntl.F_GETFL) & ~os.O_NONBLOCK)
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view):]
    except OSError as exc:
        raise error(Pos(path, 1, 1), f"cannot write output: {exc.strerror}") from None
    finally:
        os.close(fd)


def _replace(path: str, target: str, data: bytes) -> None:
    """A regular file (or none yet): a temporary file beside it, renamed over it."""
    folder = os.path.dirname(target)
    try:
        fd, tmp = tempfile.mkstemp(prefix=".max2code-", dir=folder)
    except OSError as exc:
        raise error(Pos(path, 1, 1), f"cannot write output: {exc.strerror}") from None
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.chmod(tmp, 0o644)
        os.replace(tmp, target)
        tmp = ""
    except OSError as exc:
        raise error(Pos(path, 1, 1), f"cannot write output: {exc.strerror}") from None
    finally:
        if tmp:
            try:
                os.unlink(tmp)
            except OSError:
                pass


@contextmanager
def replaced_atomically(path: str) -> Iterator[str]:
    """A temporary path beside `path` (same suffix, so writers that pick a format from the name
    still do) for a library that insists on writing a file itself (Pillow, ffmpeg); renamed over
    `path` when the block ends without an exception, removed otherwise. Errors come out as
    `path:1:1: error: ...` like every output's. As for write_if_changed, a symlink is followed
    and a device or FIFO is written into, never replaced."""
    target = os.path.realpath(path)
    descriptor = _descriptor(path)
    # (an open descriptor's file is written through it: the temporary file goes to the system's
    # folder for them, as realpath names no folder for a pipe)
    folder = tempfile.gettempdir() if descriptor is not None else os.path.dirname(target)
    suffix = os.path.splitext(path)[1]
    try:
        fd, tmp = tempfile.mkstemp(prefix=".max2code-", suffix=suffix, dir=folder)
        os.close(fd)
    except OSError as exc:
        raise error(Pos(path, 1, 1), f"cannot write output: {exc.strerror}") from None
    try:
        yield tmp
        if descriptor is not None:
            with open(tmp, "rb") as f:
                _write_fd(path, descriptor, f.read())
        elif os.path.exists(target) and not stat.S_ISREG(os.stat(target).st_mode):
            with open(tmp, "rb") as f:
                _write_into(path, target, f.read())
        else:
            os.chmod(tmp, 0o644)
            os.replace(tmp, target)
    except OSError as exc:
        raise error(Pos(path, 1, 1), f"cannot write output: {exc.strerror}") from None
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
