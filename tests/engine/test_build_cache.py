"""The engine library's build cache (max2code/engine/build.py): concurrent first uses build a
digest once and all get it; a build that finds the same build already in place keeps that one
("Directory not empty" before); pruning keeps the builds used last and never a lock a build in
progress holds. The C build itself is replaced by a stand-in that takes a while."""

from __future__ import annotations

import multiprocessing
import os
import time
from pathlib import Path

import pytest

from max2code.engine import build

KEY = "0123456789abcdef0123"


@pytest.fixture
def cache(monkeypatch, tmp_path) -> Path:
    """An empty cache, a fixed digest, no MAX2CODE_ENGINE_LIB; returns the builds' folder."""
    monkeypatch.setenv("MAX2CODE_CACHE", str(tmp_path / "cache"))
    monkeypatch.delenv("MAX2CODE_ENGINE_LIB", raising=False)
    monkeypatch.setattr(build, "digest", lambda: KEY)
    return tmp_path / "cache" / "engine"


def _slow_make(log: Path):
    def make(out: Path) -> None:
        with open(log, "a") as f:   # one line per build that ran
            f.write(f"{os.getpid()}\n")
        time.sleep(0.5)
        (out / build.LIBRARY).write_text(str(os.getpid()))
    return make


def _first_use(queue) -> None:  # pragma: no cover - runs in the forked processes
    queue.put(str(build.library()))


def test_concurrent_first_uses_build_once(cache, monkeypatch, tmp_path) -> None:
    log = tmp_path / "builds.log"
    monkeypatch.setattr(build, "_make", _slow_make(log))
    ctx = multiprocessing.get_context("fork")
    queue = ctx.Queue()
    procs = [ctx.Process(target=_first_use, args=(queue,)) for _ in range(3)]
    for p in procs:
        p.start()
    for p in procs:
        p.join(60)
    assert [p.exitcode for p in procs] == [0, 0, 0]
    paths = {queue.get(timeout=5) for _ in procs}
    lib = cache / KEY / build.LIBRARY
    assert paths == {str(lib)}
    assert len(log.read_text().split()) == 1                       # the lock held
    assert lib.read_text() == log.read_text().strip()
    assert sorted(p.name for p in cache.iterdir()) == [f".lock-{KEY}", KEY]   # no temp folder


def test_a_build_already_in_place_wins(cache, monkeypatch) -> None:
    """Another process (one that did not share the lock) renamed the same build into place
    while ours ran: ours is discarded, theirs returned, no error."""
    def make(out: Path) -> None:
        theirs = cache / KEY
        theirs.mkdir()
        (theirs / build.LIBRARY).write_text("theirs")
        (out / build.LIBRARY).write_text("ours")
    monkeypatch.setattr(build, "_make", make)
    lib = build.library()
    assert lib == cache / KEY / build.LIBRARY and lib.read_text() == "theirs"
    assert sorted(p.name for p in cache.iterdir()) == [f".lock-{KEY}", KEY]


def test_a_failed_build_leaves_nothing(cache, monkeypatch) -> None:
    def make(out: Path) -> None:
        raise build.EngineBuildError("no compiler")
    monkeypatch.setattr(build, "_make", make)
    with pytest.raises(build.EngineBuildError, match="no compiler"):
        build.library()
    assert not (cache / KEY).exists()
    assert [p.name for p in cache.iterdir()] == [f".lock-{KEY}"]


def test_prune_keeps_builds_used_last_and_live_locks(cache, monkeypatch, tmp_path) -> None:
    cache.mkdir(parents=True)
    old = time.time() - 3600
    for k in range(6):                       # build k made k minutes after the first
        d = cache / f"b{k}"
        d.mkdir()
        (d / build.LIBRARY).write_text("")
        (cache / f".lock-b{k}").write_text("")
        os.utime(d, (old + 60 * k, old + 60 * k))
    (cache / f".lock-{KEY}").write_text("")  # held by a build of KEY in progress: no folder yet
    monkeypatch.setattr(build, "digest", lambda: "b0")
    assert build.library() == cache / "b0" / build.LIBRARY   # the oldest build, used now
    build._prune(cache, keep=cache / "b5", limit=4)
    left = sorted(p.name for p in cache.iterdir())
    assert left == [f".lock-{KEY}", ".lock-b0", ".lock-b3", ".lock-b4", ".lock-b5",
                    "b0", "b3", "b4", "b5"]


def test_a_cache_shared_by_many_clones_keeps_each_ones_build(cache) -> None:
    """Clones at work on one machine share the cache: the default keeps a dozen builds, so
    eight clones that each rebuilt once still find their libraries."""
    cache.mkdir(parents=True)
    old = time.time() - 3600
    for k in range(build.KEEP_BUILDS + 3):
        d = cache / f"b{k}"
        d.mkdir()
        os.utime(d, (old + 60 * k, old + 60 * k))
    build._prune(cache, keep=cache / "b0")
    left = {p.name for p in cache.iterdir()}
    assert build.KEEP_BUILDS >= 12   # eight clones, and four of them mid-edit
    assert left == {"b0"} | {f"b{k}" for k in range(3, build.KEEP_BUILDS + 3)}
