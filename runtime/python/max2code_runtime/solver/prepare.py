"""Validation and preparation: exponents, root bounds, ``reduce``, ``normalise``
(C: ``runtime/c/roots/prepare.inc``)."""

from __future__ import annotations

import math
from typing import Sequence

from .shared import Coeffs, DBL_MAX, DBL_MIN, EPS, ceil_div, ilogb, ldexp


# ---------------------------------------------------------------------------
# Preparation
# ---------------------------------------------------------------------------


def _root_bound_exponent(c: Sequence[float], n: int, positive: bool = False) -> int | None:
    """Every root is below 2^(the result) (C root_bound_exponent); None when c_0..c_{n-1} = 0.
    With `positive`, over the c_i of the sign opposite to c_n's only: Kioustelidis' bound on
    the positive roots (None where no sign differs: no positive root)."""
    en = ilogb(c[n])
    best = None
    for i in range(n):
        if c[i] != 0 and (not positive or (c[i] < 0) != (c[n] < 0)):
            e = ceil_div(ilogb(c[i]) + 1 - en, n - i)
            best = e if best is None or e > best else best
    return None if best is None else best + 1


def root_bound(c: Sequence[float], n: int, positive: bool = False) -> float:
    """Fujiwara's bound on every root, or with `positive` Kioustelidis' on the positive ones
    (C root_bound); 0 when no term counts."""
    e = _root_bound_exponent(c, n, positive)
    if e is None:
        return 0.0
    if e >= 1024:
        return DBL_MAX
    return math.ldexp(1.0, e)


def _scaled_le(a: float, T: float, j: int, k: float, b: float) -> bool:
    """|a| T^j <= k |b| (T > 0 finite), in mantissas and exponents (C scaled_le)."""
    et = ilogb(T)
    mt = math.ldexp(T, -et)
    ea, eb, ek = ilogb(a), ilogb(b), ilogb(k)
    ma = math.ldexp(abs(a), -ea)
    mb = math.ldexp(abs(b), -eb) * math.ldexp(k, -ek)
    for _ in range(j):
        ma *= mt
        e = ma >= 2
        ma = 0.5 * ma if e else ma
        ea += et + e
    e = mb >= 2
    mb = 0.5 * mb if e else mb
    eb += ek + e
    return ea < eb or (ea == eb and ma <= mb)


def leading_far(e: Sequence[int], nz: Sequence[bool], n: int, T: float) -> bool:
    """C leading_far: the exponents alone show |c_n| T^(n-i) above 4 n eps |c_i| by a factor 8
    for every i (T finite), beyond all the roundings of the comparison -- almost always, and
    then leading_negligible needs no floating-point loop; step 0b (cleared_at_once) asks it
    so that the polynomial it tests is the one reduce keeps."""
    if not (DBL_MIN <= T <= DBL_MAX):
        return False
    # T >= 2^eT, k < 2^(ek + 1), |c| in [2^e, 2^(e + 1))
    eT, ek = ilogb(T), ilogb(4.0 * n * EPS)
    lhs = e[n] + eT  # a lower bound on log2 |c_n| T^(n-i)
    far = True
    for i in range(n - 1, -1, -1):
        far = far and (not nz[i] or lhs >= e[i] + ek + 5)
        lhs += eT
    return far


def _leading_negligible(c: Coeffs, n: int, tmax: float) -> bool:
    """C leading_negligible (in exponents where a side leaves the normal range; no loop where
    leading_far shows the answer, as C).  tmax = inf: no (reduce weighs over a finite K)."""
    T = tmax
    if math.isinf(T):
        return False
    k = 4.0 * n * EPS
    e, nz, _, _ = exponents(c, n)
    if leading_far(e, nz, n, T):
        return False
    Tp = 1.0
    for i in range(n - 1, -1, -1):
        Tp *= T
        if c[i] == 0:
            continue
        lhs, rhs = abs(c[n]) * Tp, k * abs(c[i])
        normal = DBL_MIN <= Tp <= DBL_MAX and DBL_MIN <= lhs <= DBL_MAX and rhs >= DBL_MIN
        if (lhs <= rhs) if normal else _scaled_le(c[n], T, n - i, k, c[i]):
            return True
    return False


def reduce(c: Coeffs, n: int, tmax: float, every_root: bool = False) -> tuple[int, float]:
    """Drop zero/negligible leading terms and factors of t: (the degree left or -1, the window's
    end).  With tmax = inf the leading term is weighed over (0, K], K the bound on the positive
    roots of the polynomial as it stands (with a skin, `every_root`, on every root), and where
    it is dropped the window becomes (0, K]: roots of the rest beyond K are none of the whole
    polynomial's (C reduce, whose comment has the history)."""
    while True:
        while n > 0 and c[n] == 0:
            n -= 1
        if n == 0:
            return (-1 if c[0] == 0 else 0), tmax
        if c[0] == 0:
            for i in range(n):
                c[i] = c[i + 1]
            c[n] = 0.0
            n -= 1
            continue
        T = tmax
        if math.isinf(T):
            K = root_bound(c, n, positive=not every_root)
            T = K if 0 < K < DBL_MAX else math.inf
        if _leading_negligible(c, n, T):
            tmax = T
            c[n] = 0.0
            n -= 1
            continue
        return n, tmax


def exponents(c: Sequence[float], n: int) -> tuple[list[int], list[bool], int, int]:
    """(e, nz, spread, emax) as C exponents(): spread -1 when every coefficient is 0."""
    nz = [c[i] != 0 for i in range(n + 1)]
    e = [ilogb(c[i]) if nz[i] else 0 for i in range(n + 1)]
    if not any(nz):
        return e, nz, -1, 0
    emax = max(e[i] for i in range(n + 1) if nz[i])
    return e, nz, emax - min(e[i] for i in range(n + 1) if nz[i]), emax


def normalise(c: Coeffs, n: int, emax: int, sign: float) -> int:
    """C normalise: scale exactly by sign 2^-E (sign +-1) so that max |c_i| (exponent emax) is
    in [1/2, 1); returns E.  The interval method wants p(0) > 0 and -c has c's roots: the sign
    rides on the exact scaling instead of a copy."""
    E = emax + 1
    if -1021 <= E <= 1022:
        f = sign * math.ldexp(1.0, -E)
        for i in range(n + 1):
            c[i] *= f
    else:
        for i in range(n + 1):
            c[i] = ldexp(sign * c[i], -E)
    return E
