"""A cache of Maxima results, so that a rebuild that changes nothing does not run Maxima again.

An entry is keyed by a SHA-256 of everything that affects Maxima's output: the exact script
sent to Maxima, the contents of the files that script loads, the identity of the Maxima
executable (its resolved path, size and modification time: cheap, and changed by an upgrade)
and the max2code version. Entries live in

    $MAX2CODE_CACHE, else $XDG_CACHE_HOME/max2code, else ~/.cache/max2code

as `v2/<2 hex>/<64 hex>`. Each entry starts with a line holding an HMAC-SHA256 of its key and
body under a secret private to the user (`$XDG_CONFIG_HOME/max2code/cache-key`, else
`~/.config/max2code/cache-key`, made with mode 0600 on first use, never inside the cache): an
entry that was truncated, corrupted, written by anyone else or copied from another machine (a
shared or restored cache folder) fails the check, is ignored, and is rewritten by the next
successful run. Without a usable secret (an unwritable config folder, a key file others may
write) nothing is cached.
Writers write a temporary file in the same folder and `os.replace` it: concurrent writers of
the same entry each leave a whole entry behind, never a mixture. Only successful runs are
stored (the caller decides); any failure to read or write the cache is silent, since the cache
is an optimisation, never a reason for a build to fail. `--no-cache` (or MAX2CODE_NO_CACHE=1)
bypasses it.

A second kind of entry (`results/`) serves `max2code build` the way ccache's direct mode serves
a compiler: keyed by the .mxm's bytes and path, the contents of the files it loads, Maxima's
identity and a digest of max2code's own code and templates, it holds the finished outputs, so
a rebuild of unchanged equations neither parses nor renders (and imports neither Lark nor Jinja).
An entry names its outputs relative to the output folder only (commands/build.py checks them), so even a
valid-looking entry can never make `build` write elsewhere.
"""

from __future__ import annotations

import hashlib
import hmac
import json
import os
import secrets
import stat
import tempfile
from dataclasses import dataclass
from pathlib import Path

from . import __version__

FORMAT = "max2code-cache-v2"
MAXIMA_KIND = "v2"
_enabled = True


def disable() -> None:
    """Bypass the cache for the rest of this process (the CLI's --no-cache)."""
    global _enabled
    _enabled = False


def enabled() -> bool:
    return _enabled and os.environ.get("MAX2CODE_NO_CACHE", "") in ("", "0")


def directory() -> Path:
    """The cache folder, as documented above (not created here)."""
    explicit = os.environ.get("MAX2CODE_CACHE")
    if explicit:
        return Path(explicit)
    xdg = os.environ.get("XDG_CACHE_HOME")
    if xdg:
        return Path(xdg) / "max2code"
    return Path.home() / ".cache" / "max2code"


def executable_identity(exe: str) -> str:
    """Resolved path, size and mtime of the Maxima executable: changes when Maxima changes."""
    try:
        real = os.path.realpath(exe)
        st = os.stat(real)
        return f"{real}\0{st.st_size}\0{st.st_mtime_ns}"
    except OSError:
        return exe


def key(script: str, exe: str, inputs: tuple[str, ...] = ()) -> str:
    """The entry key: a hash of the script, the loaded files' contents, Maxima and max2code."""
    return _digest((FORMAT, __version__, executable_identity(exe), script), inputs)


def _digest(parts: tuple[str, ...], inputs: tuple[str, ...]) -> str:
    h = hashlib.sha256()
    for part in parts:
        h.update(part.encode("utf-8", "surrogatepass"))
        h.update(b"\0\1")
    for path in inputs:
        h.update(path.encode("utf-8", "surrogateescape") + b"\0")
        try:
            with open(path, "rb") as f:
                h.update(hashlib.sha256(f.read()).digest())
        except OSError:
            h.update(b"<missing>")
        h.update(b"\0\1")
    return h.hexdigest()


def key_file() -> Path:
    """Where the user's cache secret lives: a config folder, never the cache folder."""
    config = os.environ.get("XDG_CONFIG_HOME") or str(Path.home() / ".config")
    return Path(config) / "max2code" / "cache-key"


_secret: bytes | None = None


def secret() -> bytes | None:
    """The user's cache secret, made on first use; None when it cannot be trusted or made."""
    global _secret
    if _secret is None:
        path = key_file()
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            try:
                fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
                with os.fdopen(fd, "w") as f:
                    f.write(secrets.token_hex(32) + "\n")
            except FileExistsError:
                pass
            info = os.stat(path)
            if info.st_uid != os.getuid() or info.st_mode & (stat.S_IWGRP | stat.S_IWOTH):
                return None  # someone else could choose our secret
            value = path.read_text().strip()
        except OSError:
            return None
        if len(value) < 32:
            return None
        _secret = value.encode()
    return _secret


def _mac(k: str, body: bytes) -> str | None:
    key_bytes = secret()
    if key_bytes is None:
        return None
    return hmac.new(key_bytes, k.encode() + b"\0" + body, hashlib.sha256).hexdigest()


def _entry_path(k: str, kind: str = MAXIMA_KIND) -> Path:
    return directory() / kind / k[:2] / k


def source_digest() -> str:
    """A digest of max2code's code, grammars and templates: what renders the outputs.

    Reading some 50 small files costs about a millisecond, and it makes the results cache
    correct in a checkout being edited, where the version number does not change.
    """
    global _source_digest
    if _source_digest is None:
        package = Path(__file__).resolve().parent
        h = hashlib.sha256(__version__.encode())
        for folder in (package, package.parent / "templates"):
            for root, dirs, files in sorted(os.walk(folder)):
                dirs[:] = sorted(d for d in dirs if d != "__pycache__")
                for name in sorted(files):
                    if name.endswith((".py", ".lark", ".j2", ".jinja", ".txt")):
                        full = os.path.join(root, name)
                        h.update(full.encode("utf-8", "surrogatepass") + b"\0")
                        try:
                            with open(full, "rb") as f:
                                h.update(hashlib.sha256(f.read()).digest())
                        except OSError:
                            pass
        _source_digest = h.hexdigest()
    return _source_digest


_source_digest: str | None = None


def result_key(*parts: str, inputs: tuple[str, ...] = ()) -> str:
    """A results-cache key: `parts` (paths, options, Maxima's identity) and file contents.
    Nothing else: not the current folder (whose modification time once made every build miss)."""
    return _digest((FORMAT, "results", source_digest(), *parts), inputs)


@dataclass(frozen=True)
class Entry:
    output: str
    seconds: float


def get(k: str) -> Entry | None:
    """The stored Maxima output for key `k`, or None when absent, corrupt or the cache is off."""
    obj = get_json(k, MAXIMA_KIND)
    try:
        return None if obj is None else Entry(str(obj["output"]), float(obj["seconds"]))
    except (KeyError, TypeError, ValueError):
        return None


def put(k: str, entry: Entry) -> None:
    put_json(k, {"seconds": entry.seconds, "output": entry.output}, MAXIMA_KIND)


def get_json(k: str, kind: str) -> dict | None:
    """The stored object for key `k` in `kind`, or None when absent, corrupt or off."""
    if not enabled():
        return None
    try:
        data = _entry_path(k, kind).read_bytes()
        head, _, body = data.partition(b"\n")
        mac = _mac(k, body)
        if mac is None or not hmac.compare_digest(head, (FORMAT + " " + mac).encode()):
            return None
        obj = json.loads(body.decode("utf-8"))
        if not isinstance(obj, dict) or obj.get("key") != k:
            return None
        return obj
    except (OSError, ValueError, TypeError, AttributeError):
        return None


def put_json(k: str, obj: dict, kind: str) -> None:
    """Store an object atomically; silently do nothing if the cache cannot be written."""
    if not enabled():
        return
    path = _entry_path(k, kind)
    body = json.dumps({"key": k, **obj}, ensure_ascii=False).encode("utf-8")
    mac = _mac(k, body)
    if mac is None:
        return
    data = (FORMAT + " " + mac).encode() + b"\n" + body
    tmp = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=".tmp-", dir=path.parent)
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
        tmp = None
    except OSError:
        pass
    finally:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass
