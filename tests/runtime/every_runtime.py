"""The default method's answers from every runtime on a list of vectors: C (the line driver),
Modula-2 (its binding of the C runtime, through gm2), Rust (roots_cli) and Python on both
backends (the pure-Python port and the C runtime through cffi).

One place for the tests that hold every language to one promise (issue 33: the infinite
window, the fuzz against the exact oracle): each asks `answers(runtime, vectors, ...)` and
judges what comes back, so a language cannot be left out by one test forgetting it.
"""
from __future__ import annotations

import math
from pathlib import Path
from typing import Sequence

import pytest

from . import paths
from . import test_fuzz_runtimes as tf
from . import test_m2_runtime as m2

RUNTIMES = ("c", "m2", "rust", "python", "python-c")
DEFAULT: tuple[paths.Call, ...] = (("interval", 0, 0.0, "interval"),)

Vector = tuple[tuple[float, ...], float]
Answer = tuple[int, float, bool]


def answers(runtime: str, vecs: Sequence[Vector], tmp: Path, monkeypatch: pytest.MonkeyPatch,
            m2_exe: Path | None = None, c_exe: Path | None = None) -> list[Answer]:
    """(status, t, graze) of the default method on every vector; t is NaN without a root.
    m2_exe: the Modula-2 driver (test_m2_runtime.drivers), needed for "m2" only; c_exe: a C
    line driver already built (test_fuzz_runtimes.build_driver), else "c" builds one in tmp."""
    if runtime == "c" and c_exe is not None:
        got = tf.run_timed(c_exe, [tf.c_line(0, c, t) for c, t in vecs])
        return [(st, t if st == 1 else math.nan, g and st == 1) for st, t, g, _ in got]
    if runtime == "m2":
        assert m2_exe is not None, "the Modula-2 driver comes from test_m2_runtime.drivers"
        lines = [m2.m2_line(0, c, t) for c, t in vecs]
        out: list[Answer] = []
        for k in range(0, len(lines), 20000):  # gm2's I/O is slow: chunks
            out += m2.run_m2(m2_exe, lines[k:k + 20000])
        return out
    got = paths.answers(runtime, vecs, tmp, monkeypatch, DEFAULT)
    return [(st, t if st == 1 else math.nan, bool(g) and st == 1) for st, t, g in got]
