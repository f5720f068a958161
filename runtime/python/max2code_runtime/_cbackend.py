"""The C runtime through cffi: thin wrappers around the compiled ``_roots_c`` module.

Kept apart from ``__init__`` so that a missing or stale extension is one ImportError, and the
pure-Python fallback takes over.  Buffers are per thread: cffi releases the GIL during the
call, so two threads must not share them.
"""
from __future__ import annotations

import math
import threading
from typing import Any, Sequence

from ._roots_c import ffi, lib  # type: ignore[import-not-found]


def _check_fresh() -> None:
    """In a checkout (the C sources beside this package), a build from other sources is stale:
    refuse it, so that the caller falls back to the pure-Python port instead."""
    from pathlib import Path

    from ._source import STAMP, source_digest

    src = Path(__file__).resolve().parent.parent.parent / "c"
    if (src / "max2code_roots.c").exists():
        stamp = STAMP.read_text().strip() if STAMP.exists() else ""
        if stamp != source_digest(src):
            raise ImportError("max2code_runtime._roots_c is stale: run python -m max2code_runtime.build")


_check_fresh()

MAX_COEFFS = 17
_local = threading.local()


def _buffers() -> tuple[Any, Any, Any]:
    try:
        return _local.bufs
    except AttributeError:
        _local.bufs = (ffi.new("double[17]"), ffi.new("double *"), ffi.new("int *"))
        return _local.bufs


def solve(cc: list[float], tmax: float, method: int, eps: float) -> tuple[int, float, bool]:
    """One polynomial (validated by the caller): (status, t, graze) as the C runtime says."""
    c, t, g = _buffers()
    n = len(cc)
    c[0:n] = cc
    if eps == 0:
        st = lib.m2c_first_root_ex(c, n - 1, tmax, t, method, g)
    else:
        st = lib.m2c_first_root_skin(c, n - 1, tmax, eps, t, g)
    if st == 1:
        return 1, t[0], bool(g[0])
    return st, math.nan, False


def solve_default(c: Any, tmax: float) -> tuple[int, float, bool]:
    """The default method on unvalidated input, the common call: the C runtime validates
    (NaN/Inf, tmax, degree); only what cffi cannot pass is checked here.  -1 for input that
    is not a sequence of 1 to 17 numbers."""
    bufs = _buffers()
    cb, t, g = bufs
    try:
        n = len(c)
        if not 0 < n <= MAX_COEFFS:
            return -1, math.nan, False
        cb[0:n] = c
        st = lib.m2c_first_root_ex(cb, n - 1, tmax, t, 0, g)
    except (TypeError, ValueError, OverflowError):
        return -1, math.nan, False
    if st == 1:
        return 1, t[0], bool(g[0])
    return st, math.nan, False


def solve_batch(rows: list[list[float]], tmax: float, eps: float) -> list[float]:
    """m2c_first_roots on M rows of one length: the roots, NaN for none or invalid."""
    m, w = len(rows), len(rows[0])
    flat = ffi.new("double[]", m * w)
    for i, r in enumerate(rows):
        flat[i * w:(i + 1) * w] = [float(x) for x in r]
    out = ffi.new("double[]", m)
    lib.m2c_first_roots(flat, m, w - 1, tmax, eps, out, ffi.NULL)
    return list(out)


def solve_batch_numpy(arr: Any, tmax: float, eps: float, np: Any) -> Any:
    """m2c_first_roots straight on a C-contiguous float64 (M, N+1) array, no copy."""
    m, w = arr.shape
    out = np.empty(m, dtype=np.float64)
    if m:
        lib.m2c_first_roots(ffi.cast("double *", ffi.from_buffer(arr)), m, w - 1, tmax, eps,
                            ffi.cast("double *", ffi.from_buffer(out)), ffi.NULL)
    return out
