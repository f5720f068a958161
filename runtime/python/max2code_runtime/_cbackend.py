"""The C runtime through cffi: thin wrappers around the compiled ``_roots_c`` module.

Kept apart from ``__init__`` so that a missing or stale extension is one ImportError, and the
pure-Python fallback takes over.  No state is kept between calls (the coefficients go to cffi
as a list, the results come back in one double), so threads need nothing of their own.
"""
from __future__ import annotations

import math
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
INVALID = (-1, math.nan, False)
_packed = lib.m2c_first_root_packed


def unpack(v: float) -> tuple[int, float, bool]:
    """(status, t, graze) from m2c_first_root_packed's one double (see _source.BINDING_C)."""
    if v > 0:
        return 1, v, False
    if v < 0:
        return 1, -v, True
    if v == 0:
        return 0, math.nan, False
    return INVALID


def solve(cc: list[float], tmax: float, method: int, eps: float) -> tuple[int, float, bool]:
    """One polynomial (validated by the caller): (status, t, graze) as the C runtime says."""
    return unpack(_packed(cc, len(cc) - 1, tmax, method, eps))


def packed_default(c: Any, tmax: float) -> float:
    """The default method on unvalidated input, the common call, as m2c_first_root_packed's one
    double (NaN for invalid input): the C runtime validates (NaN/Inf, tmax, degree); only what
    cffi cannot pass is checked here.  NaN for input that is not a sequence of 1 to 17 numbers.
    A list or tuple goes to cffi as it is (cffi fills a temporary array from it, as it would a
    kept buffer); any other sized sequence (a numpy row) is made a list first.  Something
    without a length (a generator) is NaN."""
    try:
        n = len(c)
        if not 0 < n <= MAX_COEFFS:
            return math.nan
        if type(c) is not list and type(c) is not tuple:
            c = list(c)
        return _packed(c, n - 1, tmax, 0, 0.0)
    except (TypeError, ValueError, OverflowError):
        return math.nan


def solve_default(c: Any, tmax: float) -> tuple[int, float, bool]:
    """packed_default's answer as (status, t, graze)."""
    return unpack(packed_default(c, tmax))


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
