"""max2code runtime for generated Python: time of next collision.

``first_root(c, tmax)`` is the smallest root in (0, tmax] of
``c[0] + c[1] t + ... + c[n] t^n`` (n <= 16), or None when there is none; invalid input (a NaN
or infinite coefficient, no or more than 17 coefficients, tmax NaN or <= 0) raises ValueError.
``first_root_status`` never raises: it returns (status, t, graze) with status -1 for invalid
input, as the C runtime does.  ``first_roots`` solves a batch (an (M, N+1) array) at once.

Two backends, one algorithm (runtime/c/max2code_roots.h documents it):

* ``"c"``: the C runtime itself through cffi (``max2code_runtime._roots_c``, built by
  ``python -m max2code_runtime.build`` -- scripts/setup does it), used whenever it imports;
* ``"python"``: ``solver/``, a line-by-line port of the C solver in pure Python, the fallback
  (or forced with MAX2CODE_PURE_PYTHON=1).

Both give bit-identical answers for the interval methods (the tests compare them).  Methods:
"interval" (default; critical points within Horner's rounding bound -- plus the optional
contact skin ``eps`` -- that do not change sign are touches, flagged graze), "interval-nograze"
(sign changes only) and "closed" (the quadratic for degree <= 2, the TOMS 1010 quartic for
degree 3-4, interval above 4; the Python backend runs quartic.py, a port of the C one).
"""
from __future__ import annotations

import math
import os
from typing import Any, Sequence

from . import quartic, solver

__all__ = ["first_root", "first_root_status", "first_roots", "METHODS", "BACKEND", "MAX_DEGREE"]

MAX_DEGREE = solver.MAXN
# BEGIN methods: written from runtime/methods.toml by scripts/runtime-methods
METHODS = ("interval", "interval-nograze", "closed")
_C_METHOD = {"interval": 0, "interval-nograze": 1, "closed": 3}
# END methods
REAL_TOL = math.sqrt(2.0**-52)  # |imag| <= REAL_TOL |z| counts as real (closed method)


def _load_c() -> Any:
    if os.environ.get("MAX2CODE_PURE_PYTHON"):
        return None
    try:
        from . import _cbackend
    except ImportError:
        return None
    return _cbackend


_C = _load_c()
BACKEND = "c" if _C is not None else "python"


# ---------------------------------------------------------------------------
# The pure-Python path
# ---------------------------------------------------------------------------


def _pick_first_real(roots: Sequence[complex], tmax: float) -> tuple[float, bool] | None:
    """Smallest real root in (0, tmax]; |imag| <= sqrt(eps) |z| counts as real (a
    rounding-split double root), reported as a graze."""
    best: tuple[float, bool] | None = None
    for z in roots:
        x, y = z.real, z.imag
        if not (math.isfinite(x) and math.isfinite(y)):
            continue
        if abs(y) > REAL_TOL * math.hypot(x, y) or not 0 < x <= tmax:
            continue
        if best is None or x < best[0]:
            best = (x, y != 0)
    return best


def _first_root_closed(c: list[float], n: int, tmax: float) -> tuple[float, bool] | None:
    q = [0.0, *c[:4]] if n == 3 else list(c[:5])
    try:
        roots = quartic.quartic_roots(q)
    except (ZeroDivisionError, ValueError, OverflowError):
        return None  # where C would compute NaN/Inf and discard them
    return _pick_first_real(roots, tmax)


def _valid(cc: list[float], tmax: float, eps: float) -> bool:
    return (1 <= len(cc) <= MAX_DEGREE + 1 and not math.isnan(tmax) and tmax > 0
            and all(math.isfinite(x) for x in cc) and 0 <= eps < math.inf)


def _solve_normalised(c: list[float], n: int, emax: int, tu: float, method: str, eps: float,
                      failed_w: float, dropped: Sequence[float]) -> tuple[float, bool] | None:
    """The C runtime's solve_normalised (spread within 2^MAX_SPREAD); failed_w: the window
    step 0b's test failed on (0 if none), not tested again; dropped: the leading terms reduce
    dropped (never_late weighs them)."""
    closed = method == "closed" and n <= 4
    interval = n > 2 and not closed
    # the interval method wants p(0) > 0: p = -c, same roots, the sign in the exact scaling
    sign = -1.0 if interval and c[0] < 0 else 1.0
    E = solver.normalise(c, n, emax, sign)
    if method == "interval-nograze":
        skin = -1.0
    else:
        skin = 0.0 if eps == 0 else solver.ldexp(eps, -E)
    tail = [solver.ldexp(sign * v, -E) for v in dropped]  # scaled as c
    if n <= 2:
        if n == 1:
            r = solver.div(-c[0], c[1])
            hit = (r, False) if 0 < r <= tu else None
        else:
            hit = solver.first_root_quadratic(c, tu, skin)
        if hit is not None and skin >= 0 and tail:
            return solver.late_low_degree(c, n, tail, hit)
        return hit
    if closed:
        return _first_root_closed(c, n, tu)
    # every positive root below it (with a skin, Fujiwara's on every root, as the skin's
    # contact need not be near a positive root)
    B = solver.root_bound(c, n, positive=not skin > 0)
    T = tu if tu < B else B
    found = solver.first_root_interval(c, n, T, skin, failed_w) if T > 0 else None
    if found is None:
        return None
    t, g, scanned = found
    if skin < 0:
        return t, g
    if scanned and not tail:
        return solver.late_scanned(c, n, (t, g))
    return solver.never_late(c, n, tail, (t, g))


def _solve_python(cc: list[float], tmax: float, method: str, eps: float) -> tuple[int, float, bool]:
    """The C runtime's solve(), on validated input."""
    degree = len(cc) - 1
    c = cc + [0.0] * (MAX_DEGREE + 1 - len(cc))
    # where the early exits apply: the interval methods, no skin, c_0 != 0
    early = c[0] != 0 and eps == 0 and method in ("interval", "interval-nograze")
    # Descartes on the input: no sign change (zeros skipped), c_0 != 0: no root in (0, inf).
    # (C counts the changes in the pass that reads the exponents, and reuses that pass's
    # spread when reduce drops nothing; the numbers are the same as computed here.)
    if early and solver.sign_changes(c, degree) == 0:
        return 0, math.nan, False
    # Step 0a': AM-GM, with tmax = inf
    if early and degree >= 3 and tmax == math.inf and solver.outweighed(c, degree):
        return 0, math.nan, False
    # Step 0b: the window's first exclusion test, before the preparation; where it fails, the
    # window [0, tmax] it failed on (0: not tried), which the default method does not test again
    failed_w = 0.0
    cleared = -1
    if early and degree >= 3 and tmax < math.inf:
        cleared = solver.cleared_at_once(c, degree, tmax)
        if cleared > 0:
            return 0, math.nan, False
        failed_w = tmax if cleared == 0 and method == "interval" else 0.0
    # (a test step 0b ran -- only where c_n, c_0 != 0 and the exponents show the leading term
    # far from negligible over [0, tmax] -- means reduce would drop nothing: not repeated)
    if cleared != 0:
        n, tmax = solver.reduce(c, degree, tmax, eps > 0 and method != "interval-nograze")
    else:
        n = degree
    if n <= 0:
        return 0, math.nan, False
    _, _, spread, emax = solver.exponents(c, n)
    dropped = [] if n == degree else solver.dropped_terms(cc, n)
    if spread > solver.MAX_SPREAD:
        found = solver.first_root_sliced(c, n, tmax, eps, method == "interval-nograze", dropped)
    else:
        found = _solve_normalised(c, n, emax, tmax, method, eps, failed_w, dropped)
    if found is None:
        return 0, math.nan, False
    t, graze = found
    if not (0 < t <= tmax and t < math.inf):
        return 0, math.nan, False
    return 1, t, graze


# ---------------------------------------------------------------------------
# The API
# ---------------------------------------------------------------------------


def _floats(c: Sequence[float], tmax: float, eps: float) -> tuple[list[float], float, float] | None:
    """Numbers as floats, None for anything else (strings too: C's cffi call refuses them;
    and an int too large for a float, whose conversion raises OverflowError: invalid input,
    as cffi has it)."""
    try:
        if any(isinstance(x, (str, bytes)) for x in (*c, tmax, eps)):
            return None
        return [float(x) for x in c], float(tmax), float(eps)
    except (TypeError, ValueError, OverflowError):
        return None


def first_root_status(c: Sequence[float], tmax: float = math.inf, method: str = "interval",
                      eps: float = 0.0) -> tuple[int, float, bool]:
    """(status, t, graze): status 1 = root t in (0, tmax], 0 = none there (or the first root
    is not representable: it underflows to 0 or overflows), -1 = invalid input (NaN/Inf
    coefficient, no or more than 17 coefficients, tmax NaN or <= 0, eps NaN, negative or
    infinite, unknown method, a skin eps > 0 with a method other than "interval", which alone
    has the graze check a skin widens -- as the C binding has it); t is nan unless status is
    1; graze says the root is a touch (double root without sign change, or a near-miss within
    the contact skin eps)."""
    if _C is not None and method == "interval" and eps == 0.0:
        return _C.solve_default(c, tmax)  # the common call, validated by C
    got = _floats(c, tmax, eps)
    if got is None or method not in METHODS:
        return -1, math.nan, False
    cc, tm, ep = got
    if not _valid(cc, tm, ep) or (ep != 0 and method != "interval"):
        return -1, math.nan, False
    if _C is not None:
        return _C.solve(cc, tm, _C_METHOD[method], ep)
    return _solve_python(cc, tm, method, ep)


def first_root(c: Sequence[float], tmax: float = math.inf, eps: float = 0.0) -> float | None:
    """Smallest root in (0, tmax] (tmax may be inf), or None when there is none.  eps >= 0 is
    the contact skin, in the units of c (distance squared for the shipped equations): a
    near-miss whose minimum is within eps counts as contact at the time of closest approach.
    Raises ValueError for invalid input (NaN/Inf coefficient, no or more than 17
    coefficients, tmax NaN or <= 0, eps NaN, negative or infinite)."""
    # The call a generated module makes, without a skin, straight to the C solve's packed
    # result (t, -t for a touch, 0 for none; NaN for input that the full path below then
    # reports): two Python frames fewer than through first_root_status (timeit, the old and new
    # package alternated: see README, Runtimes); tests/runtime/test_python_runtime.py compares
    # it with first_root_status on valid and invalid input.
    cb = _C
    if cb is not None and eps == 0.0:
        # (_C.solve_default's call, without its frame and tuple: NaN for what it refuses)
        try:
            v = cb.BY_LEN[len(c)](*c, tmax)
        except cb.CALL_ERRORS:
            v = math.nan
        if v > 0:
            return v
        if v < 0:
            return -v
        if v == 0:
            return None
    status, t, _ = first_root_status(c, tmax, "interval", eps)
    if status == -1:
        raise ValueError(f"max2code_runtime.first_root: invalid input (coefficients {list(c)!r}, "
                         f"tmax {tmax!r}, eps {eps!r}): coefficients must be 1 to "
                         f"{MAX_DEGREE + 1} finite numbers, tmax > 0 (inf allowed), 0 <= eps < inf")
    return t if status == 1 else None


def first_roots(C: Any, tmax: float = math.inf, eps: float = 0.0) -> Any:
    """The first root of every row of C (an (M, N+1) array or a sequence of M sequences of one
    length N+1 <= 17, c[i] multiplying t^i), NaN where a row has none or is invalid (a row
    with something that is not a number, or that no float holds, included; tmax and eps as
    first_root_status takes them: anything else makes every row NaN): a numpy array when numpy
    is installed, else a list.  One call into C for the whole batch with the C
    backend (m2c_first_roots); raises ValueError for a ragged or over-long C, or one that is
    not rows.  Both backends give the same answers on the same input, bit for bit."""
    try:
        import numpy as np
    except ImportError:
        np = None
    scalars = _floats((), tmax, eps)
    if np is not None:
        try:
            arr = np.ascontiguousarray(C, dtype=np.float64)
        except (TypeError, ValueError, OverflowError):
            # what numpy cannot convert as a whole (a row with None in a list of lists, an int
            # no float holds, a ragged list): row by row, as without numpy
            arr = np.array([_numbers_or_nan(r) for r in _rows(C)], dtype=np.float64)
        if arr.ndim == 1 and arr.shape[0] == 0:
            arr = arr.reshape(0, 1)  # [] : no rows, as without numpy
        if arr.ndim != 2 or arr.shape[1] < 1 or arr.shape[1] > MAX_DEGREE + 1:
            raise ValueError(f"first_roots: C must be (M, N+1) with 1 <= N+1 <= {MAX_DEGREE + 1}, "
                             f"not {arr.shape}")
        if scalars is None:
            return np.full(arr.shape[0], np.nan)
        _, tm, ep = scalars
        if _C is not None:
            return _C.solve_batch_numpy(arr, tm, ep, np)
        return np.array([_row(r, tm, ep) for r in arr.tolist()], dtype=np.float64)
    rows = _rows(C)
    if scalars is None:
        return [math.nan] * len(rows)
    _, tm, ep = scalars
    if _C is not None and rows:
        # a row that is not numbers is invalid, NaN, as the pure path has it
        return _C.solve_batch([_numbers_or_nan(r) for r in rows], tm, ep)
    return [_row(r, tm, ep) for r in rows]


def _rows(C: Any) -> list[list[Any]]:
    """C as rows of one length, 1 to 17 entries each (ValueError otherwise)."""
    try:
        rows = [list(r) for r in C]
    except TypeError:
        raise ValueError("first_roots: C must be M rows (sequences) of coefficients") from None
    if rows and (len({len(r) for r in rows}) != 1 or not 1 <= len(rows[0]) <= MAX_DEGREE + 1):
        raise ValueError("first_roots: C must be M rows of one length, 1 to "
                         f"{MAX_DEGREE + 1} coefficients")
    return rows


def _numbers_or_nan(r: list[Any]) -> list[float]:
    """The row as floats, or NaNs (C's invalid input) where one entry is not a number."""
    got = _floats(r, 0.0, 0.0)
    return got[0] if got is not None else [math.nan] * len(r)


def _row(r: Sequence[float], tmax: float, eps: float) -> float:
    st, t, _ = first_root_status(r, tmax, "interval", eps)
    return t if st == 1 else math.nan
