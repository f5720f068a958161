"""The C runtime through cffi: thin wrappers around the compiled ``_roots_c`` module.

Kept apart from ``__init__`` so that a missing or stale extension is one ImportError, and the
pure-Python fallback takes over.  No state is kept between calls (the coefficients go to cffi
as arguments or as a list, the results come back in one double), so threads need nothing of
their own.
"""
from __future__ import annotations

import math
from typing import Any, Sequence

from ._roots_c import ffi, lib  # type: ignore[import-not-found]
from ._source import MAX_COEFFS


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

INVALID = (-1, math.nan, False)
# m2c_packed_k by k, the number of coefficients (_source.BINDING_C): the coefficients as k
# double arguments, which cffi converts each as it does a list's items, but without building a
# temporary array from a list (timeit, a stub that only sums them, three runs: 9 floats as
# arguments 179-197 ns a call, as a list 290-345 ns).  BY_LEN[len(c)](*c, tmax) is the default
# solve of any sized sequence c; it raises one of CALL_ERRORS for anything that is not 1 to 17
# numbers, all invalid input: BY_LEN[0] is None, not callable; past 17, an IndexError; a
# string or an object cffi cannot convert, a TypeError; items fewer or more than len() says, a
# TypeError (where the array binding read past the items given or ignored the extra ones: the
# pure-Python port solves on the items it iterates); and a TypeError or IndexError that the
# sequence's own iteration raises.  An extension built from older sources, without these
# bindings, is stale: an ImportError, so that the package falls back to the pure-Python port.
try:
    _packed = lib.m2c_first_root_packed
    BY_LEN = (None, *(getattr(lib, f"m2c_packed_{k}") for k in range(1, MAX_COEFFS + 1)))
except AttributeError as exc:
    raise ImportError(f"max2code_runtime._roots_c is stale ({exc}): run python -m "
                      "max2code_runtime.build") from exc
CALL_ERRORS = (TypeError, ValueError, OverflowError, IndexError)


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


def solve_default(c: Any, tmax: float) -> tuple[int, float, bool]:
    """The default method on unvalidated input, the common call, as (status, t, graze): the C
    runtime validates (NaN/Inf, tmax, degree); only what cffi cannot pass is caught here, as
    invalid input: anything but a sized sequence of 1 to 17 numbers (a generator has no length).
    The coefficients go to C as that many arguments (BY_LEN): any sized sequence (a list, a
    tuple, a numpy row) unpacked, each item converted by cffi as a double.  (first_root makes
    the same call itself, one frame fewer, and reads the packed double.)"""
    try:
        return unpack(BY_LEN[len(c)](*c, tmax))
    except CALL_ERRORS:
        return INVALID


# m2c_first_roots counts rows in a C int: larger batches go in chunks of this many rows
CHUNK = 2**31 - 1


def solve_batch(rows: list[list[float]], tmax: float, eps: float) -> list[float]:
    """m2c_first_roots on M rows of one length (floats): the roots, NaN for none or invalid."""
    m, w = len(rows), len(rows[0])
    flat = ffi.new("double[]", m * w)
    for i, r in enumerate(rows):
        flat[i * w:(i + 1) * w] = r
    out = ffi.new("double[]", m)
    for i in range(0, m, CHUNK):
        k = min(CHUNK, m - i)
        lib.m2c_first_roots(flat + i * w, k, w - 1, tmax, eps, out + i, ffi.NULL)
    return list(out)


def solve_batch_numpy(arr: Any, tmax: float, eps: float, np: Any) -> Any:
    """m2c_first_roots straight on a C-contiguous float64 (M, N+1) array, no copy (in chunks
    of CHUNK rows)."""
    m, w = arr.shape
    out = np.empty(m, dtype=np.float64)
    c = ffi.cast("double *", ffi.from_buffer(arr))
    t = ffi.cast("double *", ffi.from_buffer(out))
    for i in range(0, m, CHUNK):
        k = min(CHUNK, m - i)
        lib.m2c_first_roots(c + i * w, k, w - 1, tmax, eps, t + i, ffi.NULL)
    return out
