"""The engine's shared library: built on first use into the cache, then reused.

The C core (`engine/` in a checkout, `max2code/_data/engine/` in an installed package) is
built by its own Makefile, which runs max2code itself to generate the equation headers from
the .mxm files (with `-MD -MP` depfiles): the same build integration users get. The result
lives in `<max2code cache>/engine/<digest>/libmax2code_engine.so`, where the digest covers
the engine's sources, the C runtime, the equations, max2code's own code (which renders the
headers) and the compiler: any change builds a fresh library, and an unchanged checkout loads
the existing one in about a millisecond. Builds go to a temporary folder of their own renamed
into place under a lock, so concurrent first uses (pytest workers, two terminals) never see half
a library; should another process have put the same build in place meanwhile, ours is discarded.
The cache keeps the few builds used last (each use touches its folder): clones and sessions
sharing one cache each build their own digest, and a library in use must not be pruned under a
long test run, whose next process would rebuild it (a compile inside a measured run).
"""

from __future__ import annotations

import fcntl
import hashlib
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from .. import __version__, cache
from ..paths import PACKAGE, ROOT, runtime_dir

LIBRARY = "libmax2code_engine.so"
ENGINE_EQUATIONS = ("circles-orbit.mxm", "circle-orbit-line.mxm")  # from equations/ (order 4)


class EngineBuildError(RuntimeError):
    """The C core could not be built (the message ends with the build's own output)."""


def engine_dir() -> Path:
    return ROOT / "engine"


def header() -> Path:
    return engine_dir() / "include" / "max2code_engine.h"


def _inputs() -> list[Path]:
    src = engine_dir()
    files = [src / "Makefile", *sorted((src / "include").glob("*.h")),
             *sorted((src / "src").glob("*.[ch]")), *sorted((src / "equations").glob("*.mxm")),
             *sorted(runtime_dir("c").glob("*.[ch]")),
             *sorted(runtime_dir("c").glob("roots/*.inc")),  # the parts max2code_roots.c includes
             *(ROOT / "equations" / name for name in ENGINE_EQUATIONS)]
    return files


def _generator_files() -> list[Path]:
    """What renders the generated C headers: max2code's generator code and the C templates
    (not the engine's own Python, the renderer or the subcommands: editing those must not
    rebuild the library)."""
    pkg = PACKAGE
    files = sorted(pkg.glob("*.py"))
    for stage in ("maxima", "front", "codegen", "languages"):
        files += sorted((pkg / stage).glob("*.py"))
    files += sorted((pkg / "front").glob("*.lark"))
    files += sorted((ROOT / "templates" / "c").glob("*"))
    return files


def digest() -> str:
    h = hashlib.sha256(__version__.encode())
    h.update((shutil.which(os.environ.get("CC", "cc")) or "cc").encode())
    for path in _inputs() + _generator_files():
        h.update(str(path.relative_to(ROOT)).encode() + b"\0")
        h.update(hashlib.sha256(path.read_bytes()).digest())
    return h.hexdigest()[:20]


def library() -> Path:
    """The path of the built library, building it first when needed."""
    explicit = os.environ.get("MAX2CODE_ENGINE_LIB")
    if explicit:
        return Path(explicit)
    key = digest()
    home = cache.directory() / "engine"
    final = home / key
    lib = final / LIBRARY
    if lib.exists():
        _touch(final)
        return lib
    home.mkdir(parents=True, exist_ok=True)
    with open(home / f".lock-{key}", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if lib.exists():
            return lib
        tmp = Path(tempfile.mkdtemp(prefix=f".{key}-", dir=home))
        try:
            _make(tmp)
            _install(tmp, final)
        except BaseException:
            shutil.rmtree(tmp, ignore_errors=True)
            raise
    _prune(home, keep=final)
    return lib


def _install(tmp: Path, final: Path) -> None:
    """Rename the finished build into place; when the same build got there first (a process
    that did not share our lock: another cache folder's lock file, an older max2code), keep that
    one and discard ours -- a rename onto a non-empty folder fails ("Directory not empty")."""
    try:
        os.replace(tmp, final)
    except OSError:
        if not (final / LIBRARY).exists():
            raise
        shutil.rmtree(tmp, ignore_errors=True)


def _touch(build: Path) -> None:
    """Mark a build as used now, for _prune (which keeps the builds used last)."""
    try:
        os.utime(build)
    except OSError:
        pass


def _make(out: Path) -> None:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [str(PACKAGE.parent), str(runtime_dir("python"))] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else []))
    cmd = ["make", "-s", "-C", str(engine_dir()), f"BUILD={out}",
           f"MAX2CODE={sys.executable} -m max2code", f"RUNTIME={runtime_dir('c')}",
           f"EQUATIONS={ROOT / 'equations'}"]
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=900)
    except (OSError, subprocess.SubprocessError) as exc:
        raise EngineBuildError(f"cannot run make for the engine: {exc}") from exc
    if proc.returncode != 0 or not (out / LIBRARY).exists():
        tail = (proc.stdout + proc.stderr)[-4000:]
        raise EngineBuildError(f"building the engine failed ({' '.join(cmd)}):\n{tail}")


# Builds kept in the cache: one per clone or session working at once, with room for each to
# make a new one per edit (6 MB each).  With 4, seven clones at work on one machine pruned each
# other's libraries, and a test's subprocess rebuilt the engine (two minutes under that load).
KEEP_BUILDS = 12


def _prune(home: Path, keep: Path, limit: int = KEEP_BUILDS) -> None:
    """Keep the builds used last (a checkout being edited makes a new one per change).
    Lock files go only with their builds: a lock whose build is still missing may be held by
    a build in progress, and unlinking it let a third process build the same digest at once."""
    builds = sorted((p for p in home.iterdir() if p.is_dir() and not p.name.startswith(".")),
                    key=lambda p: p.stat().st_mtime, reverse=True)
    for old in builds[limit:]:
        if old != keep:
            shutil.rmtree(old, ignore_errors=True)
            try:
                (home / f".lock-{old.name}").unlink()
            except OSError:
                pass
