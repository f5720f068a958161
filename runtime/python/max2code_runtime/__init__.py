"""max2code runtime for generated Python: time of next collision.

``first_root(c, tmax)`` is the smallest root in (0, tmax] of
``c[0] + c[1] t + ... + c[n] t^n`` (n <= 8), or None.  Pure Python 3.11, the
same algorithm and contract as the C runtime (runtime/c/max2code_roots.h
documents both): validation, the shared preparation (drop exact-zero and
negligible leading terms, divide out t when c[0] == 0, power-of-two
normalisation), then

* "interval" (default): critical points of the derivatives split the window
  into monotone pieces; the first sign change is polished by safeguarded
  Newton to full relative accuracy; a critical point where |p| is within
  Horner's rounding bound and p does not change sign is a touch (graze);
* "interval-nograze": the same without the touch check;
* "closed": closed forms -- the quadratic for degree <= 2, the TOMS 1010
  quartic for degree 3-4 (a cubic as t * p(t)), interval above 4.

There is no GSL method in Python.
"""
from __future__ import annotations

import math
from typing import Sequence

from . import quartic
from .roots import (
    REAL_TOL,
    first_root_interval,
    first_root_quadratic,
    is_valid,
    normalise,
    reduce,
    root_bound,
)

__all__ = ["first_root", "first_root_status", "METHODS"]

METHODS = ("interval", "interval-nograze", "closed")


def _pick_first_real(roots: Sequence[complex], tmax: float) -> tuple[float, bool] | None:
    """Smallest real root in (0, tmax]; |imag| <= sqrt(eps) |z| counts as
    real (a rounding-split double root), reported as a graze."""
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


def first_root_status(c: Sequence[float], tmax: float = math.inf, method: str = "interval") -> tuple[int, float, bool]:
    """(status, t, graze): status 1 = root t in (0, tmax], 0 = none there,
    -1 = invalid input (NaN/Inf coefficient, more than 9 or no coefficients,
    tmax NaN or <= 0, unknown method); t is nan unless status is 1; graze
    says the root is a touch (double root without sign change)."""
    try:
        cc = [float(x) for x in c]
        tmax = float(tmax)
    except (TypeError, ValueError):
        return -1, math.nan, False
    if method not in METHODS or not is_valid(cc, tmax):
        return -1, math.nan, False
    n = reduce(cc, tmax)
    if n <= 0:
        return 0, math.nan, False
    normalise(cc, n)
    graze_check = method != "interval-nograze"
    found: tuple[float, bool] | None
    if n == 1:
        r = -cc[0] / cc[1]
        found = (r, False) if 0 < r <= tmax else None
    elif n == 2:
        found = first_root_quadratic(cc, tmax, graze_check)
    elif method == "closed" and n <= 4:
        found = _first_root_closed(cc, n, tmax)
    else:
        T = min(tmax, root_bound(cc, n))  # all roots lie below the bound
        found = first_root_interval(cc, n, T, graze_check) if T > 0 else None
    if found is None:
        return 0, math.nan, False
    return 1, found[0], found[1]


def first_root(c: Sequence[float], tmax: float = math.inf) -> float | None:
    """Smallest root in (0, tmax] (tmax may be inf), or None -- for no root
    and for invalid input alike, which is what generated code wants: no
    collision to schedule."""
    status, t, _ = first_root_status(c, tmax)
    return t if status == 1 else None
