"""Coefficients spanning more than 2^MAX_SPREAD, solved by slices
(C: ``runtime/c/roots/spread.inc``)."""

from __future__ import annotations

import math
from typing import Sequence

from .shared import DBL_MIN, TRUE_MIN, div, ldexp
from .prepare import exponents
from .evaluate import scale_exponent, sign_at, within_noise
from .newton import horner_compensated
from .quadratic import first_root_quadratic
from .derivative import derivative_method
from .never_late import late_scanned, late_sliced_tail


# ---------------------------------------------------------------------------
# Extreme spreads (see the C runtime's first_root_sliced)
# ---------------------------------------------------------------------------

SLICE = 32
DOMINANCE = 6
_LO = 2.0**-16
_LO_OPEN = math.nextafter(_LO, 0.0)
_HI = 2.0**16


def _dominant_term(e: list[int], nz: list[bool], n: int, d: int) -> int | None:
    best, top, second = None, None, None
    for i in range(n + 1):
        if not nz[i]:
            continue
        v = e[i] + d * i
        if top is None or v > top:
            second, top, best = top, v, i
        elif second is None or v > second:
            second = v
    return best if second is None or top - second >= DOMINANCE else None


def first_root_sliced(c: Sequence[float], n: int, tmax: float, eps: float,
                      nograze: bool, dropped: Sequence[float] = ()) -> tuple[float, bool] | None:
    """Coefficients spanning more than 2^MAX_SPREAD (c[0] != 0, not normalised), slice by
    slice of t: the C runtime's first_root_sliced (dropped: the leading terms reduce dropped,
    in c's units, for never_late)."""
    e, nz, _, emax = exponents(c, n)
    d = (e[0] - emax - 2) // SLICE * SLICE
    while d < 1024:
        if d >= -1074 and math.ldexp(1.0, d) >= tmax:
            return None
        v = _dominant_term(e, nz, n, d)
        if v is not None and v == _dominant_term(e, nz, n, d + SLICE):
            d += SLICE
            continue
        k = d + SLICE // 2
        top = max(e[i] + k * i for i in range(n + 1) if nz[i])
        q = [ldexp(c[i], k * i - top - 1) if nz[i] else 0.0 for i in range(n + 1)]
        q = [x if abs(x) >= DBL_MIN else 0.0 for x in q]
        m = n
        while m > 0 and q[m] == 0:
            m -= 1
        if m > 0:
            tu = ldexp(tmax, -k)
            T = tu if tu < _HI else _HI
            skin = -1.0 if nograze else 0.0 if eps == 0 else ldexp(eps, -top - 1)
            hit: tuple[float, bool] | None
            if m == 1:
                r = div(-q[0], q[1])
                hit = (r, False) if _LO_OPEN < r <= T else None
            elif m == 2:
                hit = first_root_quadratic(q, T, skin, _LO_OPEN)
            else:
                s = sign_at(q, m, _LO, True)
                # within its noise at lo the fma sign may be noise: the precise value decides
                # (C says why)
                if s != 0 and within_noise(q, m, _LO, 0.0):
                    pc = horner_compensated(q, m, _LO)
                    if pc != 0:
                        s = 1 if pc > 0 else -1
                if s < 0:
                    q = [-x for x in q]
                hit = (_LO, False) if s == 0 else derivative_method(q, m, _LO, T, 0.0, skin)
                # and at the slice's end: the next slice starts from the precise sign there
                # (C says why)
                if (hit is None and s != 0 and scale_exponent(T, m) == 0
                        and within_noise(q, m, T, 0.0) and horner_compensated(q, m, T) < 0):
                    hit = (T, False)
                # never later than the first root, as unsliced (C says why)
                if hit is not None and s != 0 and skin >= 0:
                    hit = (late_sliced_tail(q, m, n, dropped, k, top, -1.0 if s < 0 else 1.0, hit)
                           if dropped else late_scanned(q, m, hit))
            if hit is not None:
                # a root at or above half the least subnormal rounds up to it (C says why)
                t = ldexp(hit[0], k)
                if t == 0 and hit[0] >= ldexp(1.0, -1075 - k):
                    t = TRUE_MIN
                return t, hit[1]
        d += SLICE
    return None
