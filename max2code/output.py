"""Writing outputs the way build systems like: atomically, and only when the content changes."""

from __future__ import annotations

import os
import sys
import tempfile

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
