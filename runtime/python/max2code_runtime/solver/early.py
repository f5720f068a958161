"""The early exits before the preparation, steps 0a' and 0b
(C: ``runtime/c/roots/early.inc``)."""

from __future__ import annotations

import math
from typing import Sequence

from .shared import EPS, MAX_SPREAD, U, ldexp
from .prepare import exponents, leading_far
from .evaluate import noise_factor
from .bernstein import bounds_positive


def outweighed(c: Sequence[float], n: int) -> bool:
    """Step 0a' (C outweighed): no root in (0, inf) by the AM-GM inequality, where every
    negative coefficient of sign(c_0) c stands alone between two positive ones:
    a t^(i-1) + b t^(i+1) >= 2 sqrt(a b) t^i for t > 0, each positive coefficient lending half
    of itself to each of two negative neighbours (all of itself to one).  Shown for the
    envelope q with twice the noise factor, so that no computed graze test sees a touch where
    this sees none; the comparison's rounding is within K.  Only with tmax = inf, where step 0b
    needs the preparation first.  c: n + 1 coefficients, c[0] != 0, n >= 3."""
    s = -1.0 if c[0] < 0 else 1.0
    e = 2 * noise_factor(n)
    k = (1 + e) / (1 - e) * (1 + 16 * U)
    if not s * c[n] > 0:
        return False
    for i in range(1, n):
        v = s * c[i]
        if not v < 0:
            continue
        a, b = s * c[i - 1], s * c[i + 1]
        if not (a > 0 and b > 0):
            return False  # a zero, or two negatives side by side
        a *= 0.5 if i >= 2 and s * c[i - 2] < 0 else 1.0  # a lends to i - 2 too
        b *= 0.5 if i + 2 <= n and s * c[i + 2] < 0 else 1.0
        if not -v * k < 2 * (math.sqrt(a) * math.sqrt(b)):
            return False
    return True


def cleared_at_once(c: Sequence[float], n: int, tmax: float) -> int:
    """Step 0b (C cleared_at_once): no root in (0, tmax] by bounds_positive at 0 over the
    whole of [0, tmax], on the coefficients as given (degree n, c[0] != 0, tmax finite, no
    skin), before reduce, the root bound and the Point at 0 -- which are most of the cost of a
    solve this test settles.  The lower bounds are those point_at_zero forms from p = c 2^-E
    sign(c_0), normalise's exact scaling, with e = noise_factor(n) (the graze check's, also
    for the no-graze method: a smaller q, so a clearing still holds), bit for bit.  Only where
    reduce keeps every term (the exponents show it) and the spread is in range, so that the
    polynomial tested is the one the full path solves.  Returns 1 (no root), 0 (the test
    failed: the default method then skips the identical test at T = tmax) or -1 (not
    tried)."""
    e, nz, spread, emax = exponents(c, n)  # (C: the Scan of load_coefficients)
    E = emax + 1
    if (not nz[n] or spread > MAX_SPREAD or E < -1021 or E > 1022
            or not leading_far(e, nz, n, tmax)):
        return -1
    f = (-1.0 if c[0] < 0 else 1.0) * math.ldexp(1.0, -E)  # exact, as in normalise
    en = noise_factor(n)
    qt = [0.0] * (n + 1)
    tol = [0.0] * (n + 1)
    for k in range(n + 1):
        p = c[k] * f
        qt[k] = p - en * abs(p)
        tol[k] = EPS * abs(p)
    return int(bounds_positive(qt, tol, n, tmax, 1))
