"""Writing outputs the way build systems like: atomically, and only when the content changes."""

from __future__ import annotations

import os
import sys
import tempfile
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
    data = text.encode("utf-8")
    try:
        with open(path, "rb") as f:
            if f.read() == data:
                return False
    except OSError:
        pass
    folder = os.path.dirname(os.path.abspath(path))
    try:
        fd, tmp = tempfile.mkstemp(prefix=".max2code-", dir=folder)
    except OSError as exc:
        raise error(Pos(path, 1, 1), f"cannot write output: {exc.strerror}") from None
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except OSError as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise error(Pos(path, 1, 1), f"cannot write output: {exc.strerror}") from None
    return True


@contextmanager
def replaced_atomically(path: str) -> Iterator[str]:
    """A temporary path beside `path` (same suffix, so writers that pick a format from the name
    still do) for a library that insists on writing a file itself (Pillow, ffmpeg); renamed over
    `path` when the block ends without an exception, removed otherwise. Errors come out as
    `path:1:1: error: ...` like every output's."""
    folder = os.path.dirname(os.path.abspath(path))
    suffix = os.path.splitext(path)[1]
    try:
        fd, tmp = tempfile.mkstemp(prefix=".max2code-", suffix=suffix, dir=folder)
        os.close(fd)
    except OSError as exc:
        raise error(Pos(path, 1, 1), f"cannot write output: {exc.strerror}") from None
    try:
        yield tmp
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except OSError as exc:
        raise error(Pos(path, 1, 1), f"cannot write output: {exc.strerror}") from None
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
