"""The C runtime's interval solver in pure Python, operation for operation.

``runtime/c/max2code_roots.c`` holds the algorithm and the reasons for each step (its header
documents the contract and tolerances); this is a line-by-line port, used when the C runtime
cannot be loaded through cffi.  Every floating-point operation is the C one in the same order,
so the answers are bit-identical to C's (the tests compare them on every hard case, random
polynomial and fuzz vector).  Where Python differs from C it is emulated:

* ``fma`` is correctly rounded: ``math.fma`` (Python 3.13+), else exact rational arithmetic
  rounded once (``Fraction`` to ``float`` rounds correctly), so it is slow but exact;
* division by zero gives C's +-inf/NaN instead of raising (``_div``), and ``ldexp`` gives
  +-inf on overflow instead of raising (``_ldexp``).
"""
from __future__ import annotations

import math
from fractions import Fraction
from typing import NamedTuple, Sequence

MAXN = 16
U = 2.0**-53
EPS = 2.0**-52
DBL_MIN = 2.0**-1022
TRUE_MIN = 2.0**-1074  # the least subnormal
DBL_MAX = 1.7976931348623157e308
SAFE_LOW = 2.0**120
SAFE_HIGH = 2.0**60
FAST_LIMIT_LOW = 2.0**100
FAST_LIMIT_HIGH = 2.0**56
MAX_ITER = 200
# after this many iterations a Newton step moving x by over 2^-10 of it in a bracket spanning
# more than a factor 8 becomes a geometric bisection (from lo = 0: hi / 2^64): far from every
# root Newton converges only linearly (see the C runtime)
SLOW_AFTER = 16
TOL_CRITICAL = 2.0**-36
TOL_LEVEL = 2.0**-28
PRECISE_FROM = 2.0**-26
GUESS_DONE = 2.0**-14  # C GUESS_DONE, GUESS_FAST: Laguerre also stops after a step below
GUESS_FAST = 2.0**-4  # GUESS_DONE (relative) at most GUESS_FAST of the step before
NOISE_STEP = 32 * U
MAX_SPLITS = 40
SPLIT_NEWTON = 2.0
MIN_WIDTH = 2.0**-20
EARLY_WIDTH = 0.25
MAX_SPREAD = 1021
INF = math.inf

Coeffs = list[float]


def _fma_exact(a: float, b: float, c: float) -> float:
    if not (math.isfinite(a) and math.isfinite(b) and math.isfinite(c)):
        return a * b + c
    try:
        return float(Fraction(a) * Fraction(b) + Fraction(c))
    except OverflowError:
        return math.inf if Fraction(a) * Fraction(b) + Fraction(c) > 0 else -math.inf


fma = getattr(math, "fma", _fma_exact)


def _div(a: float, b: float) -> float:
    """a / b with IEEE semantics (C's), never ZeroDivisionError."""
    if b != 0:
        return a / b
    if a == 0 or math.isnan(a):
        return math.nan
    return math.copysign(math.inf, a) * math.copysign(1.0, b)


def _ldexp(x: float, e: int) -> float:
    try:
        return math.ldexp(x, e)
    except OverflowError:
        return math.copysign(math.inf, x)


def ilogb(x: float) -> int:
    """2^e <= |x| < 2^(e+1), x finite and nonzero (subnormals included)."""
    return math.frexp(x)[1] - 1


def _ceil_div(num: int, den: int) -> int:
    return -((-num) // den)


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
            e = _ceil_div(ilogb(c[i]) + 1 - en, n - i)
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


def _leading_far(e: Sequence[int], nz: Sequence[bool], n: int, T: float) -> bool:
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
    _leading_far shows the answer, as C).  tmax = inf: no (reduce weighs over a finite K)."""
    T = tmax
    if math.isinf(T):
        return False
    k = 4.0 * n * EPS
    e, nz, _, _ = exponents(c, n)
    if _leading_far(e, nz, n, T):
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
            c[i] = _ldexp(sign * c[i], -E)
    return E


# ---------------------------------------------------------------------------
# Evaluation
# ---------------------------------------------------------------------------


def _scale_exponent(x: float, m: int) -> int:
    return 0 if abs(x) <= (SAFE_LOW if m <= 8 else SAFE_HIGH) else ilogb(x) + 1


def horner(c: Sequence[float], n: int, x: float, k: int, precise: bool) -> float:
    acc = c[n]
    if k == 0:
        if precise:
            for i in range(n - 1, -1, -1):
                acc = fma(acc, x, c[i])
        else:
            for i in range(n - 1, -1, -1):
                acc = acc * x + c[i]
        return acc
    xs, f, fi = _ldexp(x, -k), _ldexp(1.0, -k), 1.0
    for i in range(n - 1, -1, -1):
        fi *= f
        acc = fma(acc, xs, c[i] * fi) if precise else acc * xs + c[i] * fi
    return acc


def _horner_abs(c: Sequence[float], n: int, x: float, k: int) -> float:
    ax = abs(x)
    acc = abs(c[n])
    xs = _ldexp(ax, -k) if k else ax
    f, fi = _ldexp(1.0, -k), 1.0
    for i in range(n - 1, -1, -1):
        fi *= f
        acc = acc * xs + abs(c[i]) * fi
    return acc


def noise_factor(n: int) -> float:
    return 2.0 * (2.0 * n * U / (1.0 - 2.0 * n * U))


def _within_noise(c: Sequence[float], n: int, x: float, skin: float) -> bool:
    k = _scale_exponent(x, n)
    sk = skin if k == 0 else _ldexp(skin, -k * n)
    return abs(horner(c, n, x, k, True)) <= noise_factor(n) * _horner_abs(c, n, x, k) + sk


def _sign_at(c: Sequence[float], n: int, x: float, precise: bool) -> int:
    v = horner(c, n, x, _scale_exponent(x, n), precise)
    return (v > 0) - (v < 0)


def _band_side(c: Sequence[float], n: int, tail: Sequence[float], x: float) -> int:
    """C band_side: 1 where p(x) > 0 certainly, -1 where p(x) < 0 certainly, 0 within the
    rounding band, for p = c_0..c_n plus the terms reduce dropped, tail[j] x^(n+1+j): p's own
    by compensated Horner, the tail's by plain Horner, each within its error bound, taken
    twice."""
    g = 0.5 * noise_factor(n)  # gamma_{2n}
    v = _horner_compensated(c, n, x)
    a = _horner_abs(c, n, x, 0)
    et = 0.0
    m = len(tail)
    if m > 0:
        xp = x
        for _ in range(n):
            xp *= x  # x^(n+1)
        tv, ta = tail[m - 1], abs(tail[m - 1])
        for j in range(m - 2, -1, -1):
            tv = tv * x + tail[j]
            ta = ta * x + abs(tail[j])
        v += tv * xp
        et = noise_factor(n + m) * (ta * xp)
    eb = 2 * (U * abs(v) + g * g * a) + et
    return 1 if v > eb else -1 if v < -eb else 0


def _two_sum(a: float, b: float) -> tuple[float, float]:
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _shift_dd(c: Sequence[float], n: int, x: float, w: float) -> list[float]:
    """C shift_dd: the coefficients of p(x + w u) in u (w a power of two), by Horner's Taylor
    shift in double-double (each product split by fma, each sum by two_sum), rounded once at
    the end: near a cluster they keep what plain arithmetic cancels away."""
    hi, lo = list(c[:n + 1]), [0.0] * (n + 1)
    for k in range(n):
        for i in range(n - 1, k - 1, -1):
            ph = hi[i + 1] * x
            pl = fma(hi[i + 1], x, -ph) + lo[i + 1] * x
            sh, se = _two_sum(hi[i], ph)
            se += lo[i] + pl
            hi[i] = sh + se
            lo[i] = se - (hi[i] - sh)
    out, f = [], 1.0
    for k in range(n + 1):
        out.append((hi[k] + lo[k]) * f)
        f *= w
    return out


def _noise_chains(c: Sequence[float], n: int, x: float, y: float
                  ) -> tuple[list[float], list[float]]:
    """C noise_chains: Horner's chains for the Taylor certificates, f = p, p', p''/2, p'''/6 at
    x, and at y >= |x| the sums of |terms| g_k = sum C(i, k) |c_i| y^(i-k), k = 0..4, that bound
    their rounding and, at |z| <= y, the derivatives |p^(k)(z)| / k!."""
    f0, f1, f2, f3 = c[n], 0.0, 0.0, 0.0
    g0, g1, g2, g3, g4 = abs(c[n]), 0.0, 0.0, 0.0, 0.0
    for i in range(n - 1, -1, -1):
        f3 = f3 * x + f2
        f2 = f2 * x + f1
        f1 = f1 * x + f0
        f0 = f0 * x + c[i]
        g4 = g4 * y + g3
        g3 = g3 * y + g2
        g2 = g2 * y + g1
        g1 = g1 * y + g0
        g0 = g0 * y + abs(c[i])
    return [f0, f1, f2, f3], [g0, g1, g2, g3, g4]


def _half_curvature_floor(f: Sequence[float], g: Sequence[float], e: float, rel: float,
                          h: float) -> float:
    """C half_curvature_floor: a lower bound of p''/2 over [x - h, x + h] within [-y, y], by
    Taylor from the chains at x (_noise_chains)."""
    return f[2] * (1 - rel) - (e * g[2] + 3 * (abs(f[3]) + e * g[3]) * h + 6 * g[4] * h * h) * (1 + rel)


def _positive_through_the_noise(c: Sequence[float], n: int, r: float) -> bool:
    """C positive_through_the_noise: p certainly positive on [r - h, r] and above the fma noise
    at r - h (Taylor's bound from Horner's chains at r; the C source has it)."""
    f, gs = _noise_chains(c, n, r, r)
    (_, f1, f2, _), (g0, g1, *_) = f, gs
    e, rel = noise_factor(n), 4.0 * (n + 1) * U
    g = 0.5 * e
    v = _horner_compensated(c, n, r)
    m = v - 2 * (U * abs(v) + g * g * g0)  # p(r) >= m
    S = (abs(f1) + e * g1) * (1 + rel)  # >= |p'(r)|
    N = e * g0 * (1 + rel)  # >= the fma noise anywhere in [0, r]
    if not (m > 0 and f2 > 0):
        return False
    h = (S + math.sqrt(S * S + 4 * f2 * N)) / f2
    L = _half_curvature_floor(f, gs, e, rel, h)
    return (h < r and L > 0 and S * S < 4 * L * m * (1 - rel)
            and (m - S * h + L * h * h) * (1 - rel) > N)


def _falls_through_the_noise(c: Sequence[float], n: int, r: float) -> bool:
    """C falls_through_the_noise: p' certainly negative on [r - h, r] and p above the fma noise
    at r - h, so no crossing pair hides in the noise to the left of the crossing r (Taylor's
    bounds from Horner's chains at r, signed; the C source has it)."""
    f, gs = _noise_chains(c, n, r, r)
    (f0, f1, f2, _), (g0, g1, *_) = f, gs
    e, rel = noise_factor(n), 4.0 * (n + 1) * U
    N = e * g0 * (1 + rel)  # >= the fma noise anywhere in [0, r]
    m = f0 - N  # p(r) >= m (the chain's own noise)
    D = -(f1 + e * g1) * (1 - rel)  # <= -p'(r)
    if not (D > 0 and N > m):
        return False
    k = f2 if f2 > 0 else 0.0
    h = 4 * (N - m) / (D + math.sqrt(D * D + 4 * k * (N - m)))
    L = _half_curvature_floor(f, gs, e, rel, h)
    low = L if L < 0 else 0.0
    return h < r and D + 2 * low * h * (1 + rel) > 0 and (m + D * h + L * h * h) * (1 - rel) > N


def _inside_the_noise(c: Sequence[float], n: int, hit: tuple[float, bool], touch: bool
                      ) -> tuple[float, bool]:
    """C inside_the_noise: a touch r where p is certainly positive (compensated), found only
    because the fma value was within its noise there, or a crossing r that the derivative
    method's scan found by fma signs.  Inside that noise the scan cannot see a cluster's
    crossings: p is solved again from where the noise begins to its left, x_b (steps to the
    left, doubling, to the first point outside it, where p is certainly positive), after an
    exact-as-can-be shift of p to x_b (_shift_dd), over (x_b, r).  Its first root if it has
    one, else the answer as it was.  Not where Taylor's bounds at r show that no root hides
    there (_positive_through_the_noise for a touch, _falls_through_the_noise for a crossing)."""
    r, _ = hit
    certified = _positive_through_the_noise if touch else _falls_through_the_noise
    if _scale_exponent(r, n) != 0 or certified(c, n, r):
        return hit
    step = r * 2.0**-50
    while True:
        step *= 2
        xb = r - step
        if not xb > 0 or step > r * 2.0**-4:
            return hit
        if not _within_noise(c, n, xb, 0.0):
            break
    if not _sign_at(c, n, xb, True) > 0:
        return hit  # (left to the steps of never_late's caller: not a near miss)
    w = r - xb
    e = ilogb(w) + 1
    q = _shift_dd(c, n, xb, _ldexp(1.0, e))
    _, _, spread, emax = exponents(q, n)
    if not q[0] > 0 or spread > MAX_SPREAD:
        return hit
    normalise(q, n, emax, 1.0)
    T = _ldexp(w, -e)
    found = first_root_interval(q, n, T, 0.0, 0.0)
    if found is None:
        return hit
    t, gu = xb + _ldexp(found[0], e), found[1]
    if not t < r:
        return hit
    # q's doubles are p shifted and rounded once: near a cluster that moves q's roots by far
    # more than p's own band (INSIDE_THE_NOISE's fourth vector: 2.1e-13 late), so t is held to
    # p's compensated band as never_late holds a root (no second look inside the noise).
    d = t * 2.0**-50
    hs = _band_side(c, n, [], t if gu else t - d)
    if (hs == -1) if gu else (hs != 1):
        return _band_walk(c, n, [], t, d, hs, gu)
    return t, gu


def never_late(c: Sequence[float], n: int, tail: Sequence[float], hit: tuple[float, bool]
               ) -> tuple[float, bool]:
    """C never_late (issue 33, item 11): never later than the first root of the polynomial as
    given (c and the dropped terms, tail).  A root stands where p is certainly positive just
    before it, at r (1 - 2^-50), a touch unless p is certainly negative at it; else the
    earliest point that cannot be excluded (steps to the left, doubling, then bisection): a
    crossing where p is certainly negative there, else a touch."""
    r, g = hit
    if not 0 < r <= 2.0**60:
        return hit
    d = r * 2.0**-50  # (exact, as ldexp)
    if not d > 0:
        return hit  # (r below 2^-1024: the steps would not move)
    before = r - d
    hs = _band_side(c, n, tail, r if g else before)
    if g and hs == 1 and n >= 3 and not tail:
        return _inside_the_noise(c, n, hit, True)
    if (hs != -1) if g else (hs == 1):
        return hit
    return _band_walk(c, n, tail, r, d, hs, g)


def _band_walk(c: Sequence[float], n: int, tail: Sequence[float], r: float, d: float, hs: int,
               g: bool) -> tuple[float, bool]:
    """C band_walk: never_late's steps from a root r that does not stand (d = r 2^-50, hs p's
    band side at r - d for a crossing, at r for a touch)."""
    hi, lo, step = (r if g else r - d), 0.0, 2 * d
    while True:
        x = r - step
        if not x > 0:
            break  # lo = 0: p(0) > 0
        s = _band_side(c, n, tail, x)
        if s == 1:
            lo = x
            break
        hi, hs = x, s
        step *= 2
    while hi - lo > d:  # (to d: what a root that stands may be late by)
        mid = lo + 0.5 * (hi - lo)
        if not lo < mid < hi:
            break
        s = _band_side(c, n, tail, mid)
        if s == 1:
            lo = mid
        else:
            hi, hs = mid, s
    return hi, hs != -1


def late_scanned(c: Sequence[float], n: int, hit: tuple[float, bool]) -> tuple[float, bool]:
    """C late_scanned: never_late for a root the derivative method found, no terms dropped; a
    crossing there is then looked for again inside the fma noise to its left
    (_inside_the_noise), from where it stands or where never_late's steps left it -- where
    those steps can run (r 2^-50 > 0, r <= 2^60)."""
    crossing = not hit[1] and n >= 3
    out = never_late(c, n, [], hit)
    r = out[0]
    if crossing and r <= 2.0**60 and r * 2.0**-50 > 0:
        return _inside_the_noise(c, n, out, False)
    return out


def dropped_terms(cc: Sequence[float], n: int) -> list[float]:
    """C dropped_terms: the leading terms reduce dropped from cc (n kept after the factors of t
    it divided out), up to the last nonzero; empty where it dropped none."""
    low = next(i for i, v in enumerate(cc) if v != 0)
    top = max(max(i for i, v in enumerate(cc) if v != 0), low + n)
    return list(cc[low + n + 1:top + 1])


def quad_roots(a: float, b: float, c: float) -> tuple[tuple[float, float] | None, float]:
    """Ascending real roots of a x^2 + b x + c (a != 0) and the discriminant's sign info."""
    m = max(abs(a), max(abs(b), abs(c)))
    e = ilogb(m)
    a, b, c = _ldexp(a, -e), _ldexp(b, -e), _ldexp(c, -e)
    h = -0.5 * b
    p, q = h * h, a * c
    dp, dq = fma(h, h, -p), fma(a, c, -q)
    d = (p - q) + (dp - dq)
    if d < 0:
        return None, d
    w = h + math.copysign(math.sqrt(d), h)
    if w == 0:
        r1 = r2 = 0.0
    else:
        r1, r2 = _div(w, a), _div(c, w)
    return (min(r1, r2), max(r1, r2)), d


def first_root_quadratic(c: Sequence[float], tmax: float, skin: float,
                         lo: float = 0.0) -> tuple[float, bool] | None:
    roots, disc = quad_roots(c[2], c[1], c[0])
    if roots is not None:
        for r in roots:
            if lo < r <= tmax:
                return r, disc == 0
        return None
    if skin < 0:
        return None
    x = _div(-c[1], 2 * c[2])
    if lo < x <= tmax and _within_noise(c, 2, x, skin):
        return x, True
    return None


def _split_point(lo: float, hi: float) -> float:
    if lo == 0:
        return hi * 2.0**-10
    if hi > 8 * lo:
        return math.sqrt(lo) * math.sqrt(hi)
    return lo + 0.5 * (hi - lo)


def _horner_compensated(P: Sequence[float], m: int, x: float) -> float:
    split = 134217729.0
    tx = split * x
    xh = tx - (tx - x)
    xl = x - xh
    s, c = P[m], 0.0
    for i in range(m - 1, -1, -1):
        p = s * x
        ts = split * s
        sh = ts - (ts - s)
        sl = s - sh
        pe = ((sh * xh - p) + sh * xl + sl * xh) + sl * xl
        sn = p + P[i]
        bb = sn - p
        se = (p - (sn - bb)) + (P[i] - bb)
        c = c * x + (pe + se)
        s = sn
    return s + c


def _value_and_slope(P: Sequence[float], D: Sequence[float], m: int, x: float, k: int,
                     precise: bool) -> tuple[float, float, float]:
    """C value_and_slope; one call per Newton step of refine_root (where C counts one, so the
    control-flow test wraps it)."""
    if k != 0:
        return horner(P, m, x, k, precise), horner(D, m - 1, x, k, False), _horner_abs(P, m, x, k)
    f, df, ax, sz = P[m], D[m - 1], abs(x), abs(P[m])
    f = f * x + P[m - 1]
    sz = sz * ax + abs(P[m - 1])
    for i in range(m - 2, -1, -1):
        df = df * x + D[i]
        sz = sz * ax + abs(P[i])
        f = f * x + P[i]
    return (_horner_compensated(P, m, x) if precise else f), df, sz


# C PRECISE_NOW: _refine_root's tol for an x0 already converged (the guess's Laguerre iterate):
# full accuracy, precise from the first step
PRECISE_NOW = -1.0


def _refine_root(P: Sequence[float], D: Sequence[float], m: int, lo: float, hi: float, slo: int,
                 tol: float, x0: float) -> float:
    x = x0
    step = step_old = hi - lo
    precise = tol < 0  # PRECISE_NOW: x0 converged, precise from the first step
    tol = 0.0 if tol < 0 else tol
    stop = tol if tol > 0 else 2 * U if precise else PRECISE_FROM
    for it in range(MAX_ITER):
        k = _scale_exponent(x, m)
        f, df, size = _value_and_slope(P, D, m, x, k, precise)
        if tol == 0 and not precise and abs(f) <= noise_factor(m) * size:
            precise = True
            stop = 2 * U
            continue
        if f == 0:
            return x
        if (f > 0) == (slo > 0):
            lo = x
        else:
            hi = x
        if hi - lo <= 2 * EPS * hi or (tol > 0 and hi - lo <= tol * hi):
            if precise or tol > 0:
                return x
            precise = True
            stop = 2 * U
            continue
        if tol == 0 and hi - lo <= PRECISE_FROM * hi:
            precise = True
            stop = 2 * U
        xn = x - (_ldexp(_div(f, df), k) if k else _div(f, df))
        s = x - xn
        slow = it >= SLOW_AFTER and (lo == 0 or hi > 8 * lo) and abs(s) > 2.0**-10 * abs(xn)
        if not (lo < xn < hi) or abs(s) > 0.5 * abs(step_old) or slow:
            # (with tol > 0 too: a step in the noise that a noisy sign pushed out of the
            # bracket; bisecting from there crept to tol, see C refine_root)
            if (precise or tol > 0) and abs(s) <= NOISE_STEP * abs(x):
                return x
            far = hi * 2.0**-64
            xn = far if slow and lo == 0 and far > DBL_MIN else _split_point(lo, hi)
            s = x - xn
        step_old = step
        step = s
        if abs(s) <= stop * abs(xn) or (precise and abs(s) <= NOISE_STEP * abs(x)):
            if precise or tol > 0:
                return xn
            precise = True
            stop = 2 * U
        x = xn
    return x


# ---------------------------------------------------------------------------
# Budan-Fourier isolation
# ---------------------------------------------------------------------------


def _sign_changes(v: Sequence[float], n: int) -> int:
    count = last = 0
    for i in range(n + 1):
        s = (v[i] > 0) - (v[i] < 0)
        count += s * last < 0
        last = s if s != 0 else last
    return count


BINOM = [[float(math.comb(j + k, k)) if j + k <= MAXN else 0.0 for j in range(MAXN + 1)]
         for k in range(MAXN + 1)]


class _Point:
    """C's Point: p's and q's Taylor coefficients at x (pt, qt), their error bounds (tol)."""
    __slots__ = ("x", "px", "dpx", "vp", "vq", "pt", "qt", "tol")

    def __init__(self, x: float, px: float, dpx: float, vp: int, vq: int, pt: list[float],
                 qt: list[float], tol: list[float]):
        self.x, self.px, self.dpx, self.vp, self.vq = x, px, dpx, vp, vq
        self.pt, self.qt, self.tol = pt, qt, tol


def _point_at_zero(p: Sequence[float], n: int, e: float, skin: float) -> _Point:
    qt = [p[i] - e * abs(p[i]) for i in range(n + 1)]
    tol = [EPS * abs(p[i]) for i in range(n + 1)]
    vp = _sign_changes(p, n)
    if skin > 0:
        qt[0] -= skin
        tol[0] += EPS * skin
        vq = _sign_changes(qt, n)
    else:
        vq = vp
    return _Point(0.0, p[0], p[1], vp, vq, [p[i] for i in range(n + 1)], qt, tol)


def _point_at(tk: list[list[float]], ta: list[list[float]], e: float, skin: float, n: int,
              x: float) -> _Point | None:
    a = [0.0] * (n + 1)
    s = [0.0] * (n + 1)
    for d in range(n, -1, -1):
        for k in range(n - d + 1):
            a[k] = a[k] * x + tk[k][d]
            s[k] = s[k] * x + ta[k][d]
    rel = 8.0 * (n + 1) * U
    pt = [0.0] * (n + 1)
    qt = [0.0] * (n + 1)
    tols = [0.0] * (n + 1)
    for k in range(n + 1):
        b = a[k] - e * s[k]
        tol = rel * s[k] + DBL_MIN
        if k == 0 and skin > 0:
            b -= skin
            tol += rel * skin
        if not (abs(a[k]) > tol and abs(b) > tol):
            return None
        pt[k] = a[k]
        qt[k] = b
        tols[k] = tol
        s[k] = b
    return _Point(x, a[0], a[1], _sign_changes(a, n), _sign_changes(s, n), pt, qt, tols)


def _clearly_positive(pt: _Point, n: int, w: float, direction: int) -> bool:
    """The C runtime's first-order exclusion test, then its second-order one, at a Point."""
    return _bounds_positive(pt.qt, pt.tol, n, w, direction)


def _bounds_positive(qt: Sequence[float], tol: Sequence[float], n: int, w: float,
                     direction: int) -> bool:
    """C bounds_positive: clearly_positive's tests from q's Taylor coefficients and their error
    bounds as arrays, so that step 0b (cleared_at_once) runs them before any Point exists."""
    rel = 4.0 * (n + 1) * U

    def low(k: int) -> float:
        return (-qt[k] if direction < 0 and k % 2 else qt[k]) - tol[k]

    r3 = 0.0
    for k in range(n, 2, -1):
        lk = low(k)
        r3 = r3 * w + (-lk if lk < 0 else 0.0)
    lks = [low(k) for k in range(min(n, 2) + 1)]
    neg = r3
    for k in range(min(n, 2), 0, -1):
        neg = neg * w + (-lks[k] if lks[k] < 0 else 0.0)
    neg *= w
    L0 = lks[0]
    if L0 > neg + rel * neg:
        return True
    if n < 2:
        return False
    L1 = lks[1]
    L2 = lks[2] - r3 * w * (1 + rel)
    if not L2 > 0:
        return False
    h = _div(-L1, 2 * L2)
    h = 0.0 if h < 0 else (w if h > w else h)
    m = L0 + h * (L1 + h * L2)
    size = abs(L0) + h * (abs(L1) + h * L2)
    return m > 2 * rel * size


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
    """Step 0b (C cleared_at_once): no root in (0, tmax] by _bounds_positive at 0 over the
    whole of [0, tmax], on the coefficients as given (degree n, c[0] != 0, tmax finite, no
    skin), before reduce, the root bound and the Point at 0 -- which are most of the cost of a
    solve this test settles.  The lower bounds are those _point_at_zero forms from p = c 2^-E
    sign(c_0), normalise's exact scaling, with e = noise_factor(n) (the graze check's, also
    for the no-graze method: a smaller q, so a clearing still holds), bit for bit.  Only where
    reduce keeps every term (the exponents show it) and the spread is in range, so that the
    polynomial tested is the one the full path solves.  Returns 1 (no root), 0 (the test
    failed: the default method then skips the identical test at T = tmax) or -1 (not
    tried)."""
    e, nz, spread, emax = exponents(c, n)  # (C: the Scan of load_coefficients)
    E = emax + 1
    if (not nz[n] or spread > MAX_SPREAD or E < -1021 or E > 1022
            or not _leading_far(e, nz, n, tmax)):
        return -1
    f = (-1.0 if c[0] < 0 else 1.0) * math.ldexp(1.0, -E)  # exact, as in normalise
    en = noise_factor(n)
    qt = [0.0] * (n + 1)
    tol = [0.0] * (n + 1)
    for k in range(n + 1):
        p = c[k] * f
        qt[k] = p - en * abs(p)
        tol[k] = EPS * abs(p)
    return int(_bounds_positive(qt, tol, n, tmax, 1))


# bernstein_test's answers
BERN_UNKNOWN = 0
BERN_CLEAR = 1
BERN_ONE = 2
# INV_BINOM[n][k] = 1.0 / C(n, k), rounded once as C's constant expressions `1.0 / 3` are
# (the integer is exact as a double; tests compare the table with the C source's)
INV_BINOM = [[1.0 / math.comb(n, k) for k in range(n + 1)] for n in range(MAXN + 1)]


def _binomial_sums(a: list[float], n: int) -> None:
    """In place, b_j = sum_{k <= j} C(j, k) a_k as C binomial_sums adds: n rounds of running
    sums, round r adding each entry j >= r's left neighbour, j descending (C writes the rounds
    out up to degree 8; tests/runtime/test_c_kernels.py checks that they give this loop's
    values bit for bit)."""
    for r in range(1, n + 1):
        for j in range(n, r - 1, -1):
            a[j] += a[j - 1]


class _BernQ(NamedTuple):
    """C BernQ: q's Bernstein coefficients on the tested interval, the bound on their errors,
    and whether q's signs are certain with an even count: only then can bernstein_clear show
    q > 0 there."""
    b: tuple[float, ...]
    err: float
    even: bool


class _Bernstein(NamedTuple):
    """What C bernstein_test finds: its answer, p(x + w) (NaN when p's coefficients were not
    formed) and q's coefficients (None unless asked, or when the answer is BERN_CLEAR)."""
    answer: int
    pend: float
    q: _BernQ | None


def _bernstein_test(pt: _Point, n: int, w: float, keep: bool) -> _Bernstein:
    """Descartes' rule on the Bernstein coefficients of q, then p, on [x, x + w] (C
    bernstein_test, which says why).  keep is C's call with qb (the test of (0, T] before the
    Taylor table): q's coefficients are kept for bernstein_clear.  p's are formed only when
    q's count is certainly 1."""
    inv = INV_BINOM[n]
    ap = [0.0] * (n + 1)
    aq = [0.0] * (n + 1)
    rel = 4.0 * (2 * n + 4) * U
    wk, g = 1.0, 0.0
    for k in range(n + 1):
        f = wk * inv[k]
        ap[k] = pt.pt[k] * f
        aq[k] = pt.qt[k] * f
        g += (pt.tol[k] + rel * (abs(pt.pt[k]) + abs(pt.qt[k]))) * wk
        wk *= w
    tol = 2 * g + DBL_MIN
    _binomial_sums(aq, n)
    certain, vq, clear = _bernstein_signs(aq, tol)
    if clear and certain:
        return _Bernstein(BERN_CLEAR, math.nan, None)
    q = _BernQ(tuple(aq), tol, certain and vq % 2 == 0) if keep else None
    # (an odd count for p means p(x + w) < 0, so q(x + w) < 0 too: q's count is odd, and
    # q.even already false)
    if not (certain and vq == 1):
        return _Bernstein(BERN_UNKNOWN, math.nan, q)
    _binomial_sums(ap, n)
    certain = certain and all(abs(v) > tol for v in ap)
    one = certain and _sign_changes(ap, n) == 1
    return _Bernstein(BERN_ONE if one else BERN_UNKNOWN, ap[n], q)


def _bernstein_signs(b: Sequence[float], tol: float) -> tuple[bool, int, bool]:
    """(every |b_j| > tol, sign changes, every b_j > 0) -- zeros not skipped (unlike
    _sign_changes: a certain coefficient is never 0)."""
    certain, clear = True, True
    changes = last = 0
    for v in b:
        s = (v > 0) - (v < 0)
        certain = certain and abs(v) > tol
        changes += s * last < 0
        last = s
        clear = clear and s > 0
    return certain, changes, clear


def _halves(b: Sequence[float], n: int) -> tuple[list[float], list[float]]:
    """The Bernstein coefficients of both halves of the interval: de Casteljau at 1/2, one
    triangle of averages, left[k] its first entry after round k and right[n - k] its last
    (C halves, whose degree-8 written-out form gives this loop's values)."""
    w = [b[j] for j in range(n + 1)]
    left = [0.0] * (n + 1)
    right = [0.0] * (n + 1)
    left[0] = w[0]
    right[n] = w[n]
    for k in range(1, n + 1):
        for j in range(n - k + 1):
            w[j] = (w[j] + w[j + 1]) * 0.5
        left[k] = w[0]
        right[n - k] = w[n - k]
    return left, right


CLEAR_DEPTH = 12
# a dip counts for a first split when it is at least this fraction of the interval from either
# end (C DIP_INSIDE: _bernstein_clear, _isolate_first_root)
DIP_INSIDE = 0.0625


def _split_at(b: Sequence[float], n: int, t: float) -> tuple[list[float], list[float]]:
    """The Bernstein coefficients of [0, t] and [t, 1] of the interval: de Casteljau at t,
    n rounds of w_j + t (w_{j+1} - w_j) (C split_at)."""
    w = [b[j] for j in range(n + 1)]
    left = [0.0] * (n + 1)
    right = [0.0] * (n + 1)
    left[0] = w[0]
    right[n] = w[n]
    for k in range(1, n + 1):
        for j in range(n - k + 1):
            w[j] = w[j] + t * (w[j + 1] - w[j])
        left[k] = w[0]
        right[n - k] = w[n - k]
    return left, right


def _bernstein_clear(q: _BernQ, n: int, t0: float) -> bool:
    """q > 0 on q's interval, shown by depth-first splitting in the Bernstein basis, the left
    piece first, the first split at t0 (where p dips) when it is well inside, the others
    halves (C bernstein_clear, which says why and bounds the pieces' errors)."""
    stack = [(q.b, q.err, 0)]
    while stack:
        b, e, d = stack.pop()
        lo = hi = b[0]
        amin = abs(b[0])
        for j in range(1, n + 1):
            v = b[j]
            lo = v if v < lo else lo
            hi = v if v > hi else hi
            amin = abs(v) if abs(v) < amin else amin
        # every sign certain (no zeros): an odd count exactly when the end signs differ
        if not (amin > e) or (b[0] > 0) != (b[n] > 0):
            return False
        if lo > 0:
            continue
        M = -lo if -lo > hi else hi
        if d == CLEAR_DEPTH:
            return False
        at = d == 0 and DIP_INSIDE < t0 < 1 - DIP_INSIDE
        left, right = _split_at(b, n, t0) if at else _halves(b, n)
        ec = e + (8 if at else 2) * n * U * M + DBL_MIN
        stack.append((right, ec, d + 1))
        stack.append((left, ec, d + 1))
    return True


SPECULATE_STEPS = 8
# the certificate's interval (0, r + r 2^-20]: 0x1p-20
SPECULATE_MARGIN = 9.5367431640625e-07
# the touch signature (C speculate_first_root says why and how they were measured): up to
# TOUCH_EXTRA Laguerre steps beyond SPECULATE_STEPS while TOUCH_STEADY step ratios in a row
# stay in [TOUCH_RATIO_LO, TOUCH_RATIO_HI] (linear convergence to a double root), then up to
# TOUCH_STEPS Newton steps on p'; a touch where p is within TOUCH_NEAR rounding bounds
TOUCH_EXTRA = 4
TOUCH_STEPS = 6
TOUCH_RATIO_LO = 0.25
TOUCH_RATIO_HI = 0.31
TOUCH_STEADY = 3
GUESS_NEWTON = 2  # Newton steps that may take Laguerre's place (complex roots in the way)
TOUCH_NEAR = 2.0**20
# half-width (relative) of the interval around a touch that goes to the derivative method
TOUCH_WIDTH = 2.0**-10


def _laguerre_terms(p: Sequence[float], n: int, x: float) -> tuple[float, float, float]:
    """p, p' and p''/2 at x by three Horner chains in C's statement order: one step of C
    speculate_first_root, Laguerre's or Newton's on p', which C counts as 3 n multiply-adds in
    phase 2 (its own function so the control-flow test can count the steps).  At x = 0 (the
    first step, only there) the coefficients, the values the chains give, as C reads them."""
    if x == 0:
        return p[0], p[1], p[2]
    f, d1, d2 = p[n], 0.0, 0.0
    for i in range(n - 1, -1, -1):
        d2 = d2 * x + d1
        d1 = d1 * x + f
        f = f * x + p[i]
    return f, d1, d2


class _Guess(NamedTuple):
    """What C speculate_first_root finds: its root (None where it returns 0) and *touch (0
    unless Newton on p' reached a critical point where p is within TOUCH_NEAR rounding
    bounds)."""
    root: float | None
    touch: float
    dip: float = 0.0  # where p dips towards complex roots near the axis (C's *dip), or 0
    over: float = 0.0  # > 0: a step went past a root (C's OVERSHOT), p < 0 here; root: Newton's start


def _speculate_first_root(p: Sequence[float], n: int, T: float) -> _Guess:
    """A guess at the first root of p in (0, T), or at a touch before it, as C
    speculate_first_root (which says when and why it gives up): Laguerre's method from 0, each
    step to the right.  Not Newton from where the control polygon crosses 0, as before: from
    far away Newton creeps (while p ~ x^n a step is about x / n, and the window is 17 times the
    first root at the median), whereas for real roots Laguerre from 0 converges monotonically
    to the first root after 0, cubically near it.  A double root ahead shows as linear
    convergence, a steady step ratio (0.284 at degree 8); then Newton on p' goes to the
    critical point -- a simple root of p', quadratic convergence where Laguerre crawls -- and
    reports it as a touch when p there is near the rounding bound.  A step that lands past a
    root (complex roots near it, or one rounding past a converged root) is reported with over,
    the point where p < 0, and root, Newton's start inside the step; where Laguerre's square
    root's argument is negative and p falls, a Newton step takes its place (GUESS_NEWTON times
    at most).  No Newton step is counted
    (C counts none here, neither Laguerre's nor those on p').  Python's float division
    overflows to inf as C's does; the step's denominator and s / last may be 0 (_div gives C's
    inf or NaN), and the test of u comes before sqrt, which raises on a negative argument where
    C's would give NaN."""
    x = last = qprev = xprev = dip = 0.0  # dip: C's *dip, set wherever the guess saw one
    critical = steady = 0  # Newton on p' (after the double-root signature)
    newton = 0  # Newton steps in Laguerre's place
    for it in range(SPECULATE_STEPS + TOUCH_EXTRA + TOUCH_STEPS):
        if not critical and it >= SPECULATE_STEPS and (
                steady == 0 or it >= SPECULATE_STEPS + TOUCH_EXTRA):
            return _Guess(None, 0.0, dip)
        f, d1, d2 = _laguerre_terms(p, n, x)
        if critical:
            # Newton on p' towards the critical point: a simple root of p' where p'' > 0 (a
            # minimum of p > 0)
            if not (d2 > 0):
                return _Guess(None, 0.0, dip)
            s = d1 / (2 * d2)
            x -= s
            if not (x > 0 and x < T):
                return _Guess(None, 0.0, dip)
            if abs(s) <= PRECISE_FROM * x:
                near = abs(f) <= TOUCH_NEAR * noise_factor(n) * _horner_abs(p, n, x, 0)
                return _Guess(None, x, dip) if near else _Guess(None, 0.0, x)  # (else a dip)
            if critical > 1 and not (abs(s) <= 0.5 * abs(last)):
                return _Guess(None, 0.0, dip)
            critical += 1
            last = s
            continue
        if f == 0:
            return _Guess(x if x > 0 else None, 0.0, dip)
        if f < 0:  # past a root: one in (xprev, x); Newton from x if it stays inside
            y = x - _div(f, d1)
            return _Guess(y if xprev < y < x else xprev + 0.5 * (x - xprev), 0.0, dip, x)
        # (n - 1) f^2 times Laguerre's discriminant: its sign, and the step from one division
        u = (n - 1) * (d1 * d1) - 2 * n * (f * d2)
        if not (u >= 0):
            # complex roots in the way (or NaN): Newton on p' towards the dip, and in
            # Laguerre's place, up to GUESS_NEWTON times while p falls, a Newton step
            if d2 > 0:
                dip = x - _div(d1, 2 * d2)
            if newton == GUESS_NEWTON or not (d1 < 0):
                return _Guess(None, 0.0, dip)
            newton += 1
            s = f / d1
        else:
            s = _div(n * f, d1 - math.copysign(math.sqrt((n - 1) * u), f))  # to the right: < 0
        if not (s < 0):
            return _Guess(None, 0.0, dip)
        xprev = x
        x -= s
        if not (x > 0 and x < T):
            return _Guess(None, 0.0, dip)
        q = _div(s, last) if it > 0 else 0.0
        if abs(s) <= PRECISE_FROM * x or (abs(s) <= GUESS_DONE * x and q <= GUESS_FAST):
            return _Guess(x, 0.0, dip)
        steady = steady + 1 if TOUCH_RATIO_LO <= q <= TOUCH_RATIO_HI else 0
        if steady >= TOUCH_STEADY:
            critical = 1  # linear convergence: a double root ahead
            last = s
            continue
        # from the fifth step on, a step that has neither halved nor shrunk by more than the
        # one before: Laguerre far from every root creeps, then speeds up; give up only while
        # it is not slowing down
        if it >= 4 and not (abs(s) <= 0.5 * abs(last)) and not (q < qprev):
            return _Guess(None, 0.0, dip)
        qprev = q
        last = s
    return _Guess(None, 0.0, dip)


def _derivative(p: Sequence[float], n: int) -> list[float]:
    """The coefficients of p' (p of degree n)."""
    return [(i + 1) * p[i + 1] for i in range(n)]


def _polish_isolated(p: Sequence[float], n: int, a: float, b: float, pa: float,
                     pb: float) -> float:
    """The one simple root of p in (a, b), p(a) = pa > 0 > pb = p(b): safeguarded Newton from
    the regula falsi point (C polish_isolated)."""
    dp = _derivative(p, n)
    x0 = a + (b - a) * _div(pa, pa - pb)
    if not (a < x0 < b):
        x0 = _split_point(a, b)
    return _refine_root(p, dp, n, a, b, 1, 0.0, x0)


def _isolation_split(a: float, b: float) -> float:
    if a == 0:
        return b * 0.0625
    if b > 8 * a:
        return math.sqrt(a) * math.sqrt(b)
    return a + 0.5 * (b - a)


_CLEARED = object()


def _isolate_first_root(p: Sequence[float], n: int, skin: float, T: float, failed_w: float):
    """(t, graze, scanned), _CLEARED, or a float: the left end left to the derivative method
    (scanned: the hit is its, first_root_interval).  failed_w:
    the window step 0b's test failed on (cleared_at_once; 0 when not tried), whose first
    _clearly_positive is that very test when T equals it: skipped then, as C does."""
    e = noise_factor(n) if skin >= 0 else 0.0
    sk = skin if skin > 0 else 0.0
    a = _point_at_zero(p, n, e, sk)
    if not (a.qt[0] - a.tol[0] > 0):
        return 0.0
    # Descartes, or q(0) beats every negative term (unless that very test failed already)
    if a.vq == 0 or (T != failed_w and _clearly_positive(a, n, T, 1)):
        return _CLEARED
    # A guess first, then a certificate: the guess (Laguerre from 0) and one Bernstein test on
    # (0, r (1 + 2^-20)] settle most solves with a root, which the test on the whole window
    # before them only delayed (measured: see the C source).
    guess = _speculate_first_root(p, n, T)
    r = guess.root
    if r is not None:
        end = guess.over if guess.over > 0 else r  # (overshot: up to the step's end)
        w = end + end * SPECULATE_MARGIN
        w = w if w < T else T
        if _bernstein_test(a, n, w, False).answer == BERN_ONE:
            tol = 0.0 if guess.over > 0 else PRECISE_NOW
            return _refine_root(p, _derivative(p, n), n, 0.0, w, 1, tol, r), False, False
    frm = 0.0  # > 0: (0, frm] is settled, the counts go on from it (C's `from`)
    # A touch ahead, with the graze check only: (0, lo] certified clear by the Bernstein test,
    # then the derivative method on (lo, hi] -- small, so few roots of the derivatives in it
    # -- instead of Taylor points bisecting down to the touch; the counts go on from hi if it
    # finds nothing.  hi is 3 widths to the right: from the middle of a symmetric interval the
    # fma noise of p' at the critical point sent the derivative method's Newton into
    # bisection (see the C source).  Before the test on the whole window, which a touch ahead
    # leaves undecided (q dips to 0 there; see the C source).
    touch = guess.touch
    if touch > 0 and skin >= 0:
        lo = touch - touch * TOUCH_WIDTH
        hi = touch + 3 * touch * TOUCH_WIDTH
        hi = hi if hi < T else T
        if _bernstein_test(a, n, lo, False).answer == BERN_CLEAR:
            # p convex around the touch, its critical point certified in one pass
            # (_touch_critical), else the derivative method (see the C source)
            d: list[list[float]] = [[] for _ in range(n)]  # rows n - 1, n - 2 only
            d[n - 1] = _derivative(p, n)
            d[n - 2] = _derivative(d[n - 1], n - 1)
            b = _touch_critical(p, d, n, lo, hi, touch)
            hit = (_scan_pieces(p, d, n, lo, hi, [b], skin, b) if b > 0 else
                   _derivative_method(p, n, lo, hi, touch, skin))
            # (on (lo, hi], convex by _touch_critical's certificate, p falls to b alone: no
            # crossing pair can hide there, not scanned)
            if hit is not None:
                return (*hit, not b > 0)
            if hi == T:
                return _CLEARED
            frm = hi
    if frm == 0:  # the whole window, unless a touch's interval settled (0, frm]
        start = _bernstein_test(a, n, T, True)
        if start.answer == BERN_CLEAR:
            return _CLEARED
        if start.answer == BERN_ONE:
            return _polish_isolated(p, n, 0.0, T, a.px, start.pend), False, False
        q = start.q
        assert q is not None  # (asked for, and not cleared)
        if q.even and _bernstein_clear(q, n, _div(guess.dip, T)):  # (after a guess that failed)
            return _CLEARED
    tk = [[BINOM[k][j] * p[j + k] if j + k <= n else 0.0 for j in range(n + 1)] for k in range(n + 1)]
    ta = [[abs(v) for v in row] for row in tk]
    first = _point_at(tk, ta, e, sk, n, T)
    if first is None:
        return frm
    if frm > 0:  # the counts start from frm: its Point, q's sign there certain
        a = _point_at(tk, ta, e, sk, n, frm)
        if a is None or not (a.qt[0] - a.tol[0] > 0):
            return frm
    stack = [first]
    splits = 0
    tested = frm == 0  # (0, T] has had its Bernstein test
    early_tried = False
    while True:
        b = stack[-1]
        w = b.x - a.x
        odd = (a.vp - b.vp) % 2 != 0
        if a.vq == b.vq or (not odd and (_clearly_positive(a, n, w, 1) or _clearly_positive(b, n, w, -1))):
            a = stack.pop()
            tested = False
            if not stack:
                return _CLEARED
            continue
        if a.vp - b.vp == 1 and a.vq - b.vq == 1:
            return _polish_isolated(p, n, a.x, b.x, a.px, b.px), False, False
        # Bernstein only for an odd count (a root certain), and not again on (0, T]
        if odd and not tested and _bernstein_test(a, n, w, False).answer == BERN_ONE:
            return _polish_isolated(p, n, a.x, b.x, a.px, b.px), False, False
        tested = False
        # two roots in (a, b] by both counts within a quarter of b (mostly a touch): to the
        # derivative method at once, once per solve; else split, at the tangent rule's point,
        # or just beyond a when the tangent meets 0 within MIN_WIDTH of it (see the C source)
        early = (not early_tried and a.vp - b.vp == 2 and a.vq - b.vq == 2
                 and w <= EARLY_WIDTH * b.x)
        early_tried = early_tried or early
        if not early:
            m = _isolation_split(a.x, b.x)
            mt = a.x + SPLIT_NEWTON * _div(-a.px, a.dpx)
            hair = a.x + 4 * MIN_WIDTH * b.x
            if splits == 0 and a.x + DIP_INSIDE * w < guess.dip < b.x - DIP_INSIDE * w:
                m = guess.dip  # the first split where the failed guess saw p dip (C says why)
            elif a.dpx < 0 and a.x < mt < b.x and mt - a.x > MIN_WIDTH * b.x:
                m = mt
            elif a.dpx < 0 and mt > a.x and mt - a.x <= MIN_WIDTH * b.x and hair < b.x:
                m = hair
            if splits < MAX_SPLITS and w > MIN_WIDTH * b.x and a.x < m < b.x:
                pt = _point_at(tk, ta, e, sk, n, m)
                if pt is not None:
                    splits += 1
                    stack.append(pt)
                    continue
        hit = _derivative_method(p, n, a.x, b.x, 0.0, skin)
        if hit is not None:
            return (*hit, True)
        if not (b.qt[0] - b.tol[0] > 0):
            return b.x
        a = stack.pop()
        if not stack:
            return _CLEARED


# ---------------------------------------------------------------------------
# Derivative method
# ---------------------------------------------------------------------------


def _derivative_chain(c: Sequence[float], n: int) -> list[list[float]]:
    d = [[0.0] * (MAXN + 1) for _ in range(n + 1)]
    d[n][: n + 1] = c[: n + 1]
    for m in range(n, 1, -1):
        d[m - 1][:m] = _derivative(d[m], m)
    return d


def _roots_in_pieces(P, D, m: int, lo: float, crit: list[float], T: float, tol: float,
                     x0: float = 0.0) -> list[float]:
    out = []
    a = lo
    sa = _sign_at(P, m, lo, False)
    for j in range(len(crit) + 1):
        b = crit[j] if j < len(crit) else T
        sb = _sign_at(P, m, b, False)
        if sb == 0:
            if j < len(crit):
                out.append(b)
        elif sa != 0 and sa != sb:
            out.append(_refine_root(P, D, m, a, b, sa, tol, x0 if a < x0 < b else _split_point(a, b)))
        a, sa = b, sb
    return out


def _convex_on(d: list[list[float]], n: int, lo: float, T: float) -> bool:
    """C convex_on: p'' certainly positive on [lo, T], beyond the rounding of its plain Horner
    value anywhere there (the C source has the bound); then the level for the roots of p'' is
    empty whatever the levels below find, and the roots of p' come from an empty level."""
    if n < 4 or not lo >= 0 or _scale_exponent(T, n) != 0:
        return False
    m = lo + 0.5 * (T - lo)
    h = m - lo if m - lo > T - m else T - m
    v = horner(d[n - 2], n - 2, m, 0, False)
    slope = _horner_abs(d[n - 3], n - 3, T, 0)
    size = _horner_abs(d[n - 2], n - 2, T, 0)
    rel = 4.0 * (n + 1) * U
    return v - h * slope * (1 + rel) > 2 * noise_factor(n) * size * (1 + rel)


def _critical_points(d: list[list[float]], n: int, lo: float, T: float, x0: float) -> list[float]:
    if _convex_on(d, n, lo, T):  # the roots of p' alone (Newton from x0 if inside)
        return _roots_in_pieces(d[n - 1], d[n - 2], n - 1, lo, [], T, TOL_CRITICAL, x0)
    level: list[float] = []
    roots, _ = quad_roots(d[2][2], d[2][1], d[2][0])
    if roots is not None:
        for r in roots:
            if lo < r < T and (not level or r > level[-1]):
                level.append(r)
    for m in range(3, n):
        tol = TOL_CRITICAL if m == n - 1 else TOL_LEVEL
        level = _roots_in_pieces(d[m], d[m - 1], m, lo, level, T, tol)
    return level


def _crossing_before_critical(c: Sequence[float], d: list[list[float]], n: int, a: float,
                              b: float, sa: int, pb: float) -> float:
    """The root of p in (a, b], p monotone from sign sa at a to pb = p(b) (precise, the other
    sign) at the critical point b: Newton from where p(b) + p''(b) (x - b)^2 / 2 meets 0 (for a
    touch within rounding of the root; from the middle it crawls), else from the split point."""
    x0 = _split_point(a, b)
    h2 = _div(-2 * pb, horner(d[n - 2], n - 2, b, 0, False))
    xq = b - math.sqrt(h2 if h2 > 0 else 0.0)
    if a < xq < b:
        x0 = xq
    return _refine_root(c, d[n - 1], n, a, b, sa, 0.0, x0)


def _touch_point(d: list[list[float]], n: int, b: float) -> float:
    """C touch_point: where a touch is reported -- the critical point b, which plain Newton on
    p' leaves anywhere within p''s rounding noise, moved by one Newton step on p' evaluated
    precisely (compensated), kept only when that step is within the noise too (b unscaled)."""
    if _scale_exponent(b, n - 1) != 0:
        return b
    v, slope, _ = _value_and_slope(d[n - 1], d[n - 2], n - 1, b, 0, True)
    x = b - _div(v, slope)
    return x if abs(x - b) <= NOISE_STEP * abs(b) else b


def _derivative_method(c: Sequence[float], n: int, lo: float, T: float, x0: float, skin: float):
    """C derivative_method: the critical points in (lo, T), then _scan_pieces."""
    d = _derivative_chain(c, n)
    return _scan_pieces(c, d, n, lo, T, _critical_points(d, n, lo, T, x0), skin)


def _touch_critical(p: Sequence[float], d: list[list[float]], n: int, lo: float, hi: float,
                    x: float) -> float:
    """C touch_critical: the critical point of p in (lo, hi) around the guess's touch x,
    certified in one pass (p convex on [lo, hi], p' < 0 at lo and > 0 at hi, from Horner's
    chains for p', p''/2, p'''/6 at x and bounds at hi; the C source has the bound), found as
    the derivative method finds it (its first Newton step on p' from x, ending there within
    TOL_CRITICAL); 0 where the pass cannot tell.  d[n - 1], d[n - 2]: p', p''."""
    # (a bracket below TOL_CRITICAL would end refine_root before its step: left to it)
    if not (lo >= 0 and lo < x and hi - x > TOL_CRITICAL * hi) or _scale_exponent(hi, n) != 0:
        return 0.0
    f, g = _noise_chains(p, n, x, hi)
    e, rel = noise_factor(n), 4.0 * (n + 1) * U
    h = x - lo if x - lo > hi - x else hi - x
    L = _half_curvature_floor(f, g, e, rel, h)
    slope = (abs(f[1]) + e * g[1]) * (1 + rel)  # >= |p'(x)|
    if not (L > 0 and slope < 2 * L * (x - lo) * (1 - rel) and slope < 2 * L * (hi - x) * (1 - rel)):
        return 0.0
    # refine_root's first step on p' from x (tol TOL_CRITICAL), and its stop
    v, df, _ = _value_and_slope(d[n - 1], d[n - 2], n - 1, x, 0, False)
    if v == 0:
        return x
    b = x - _div(v, df)
    return b if lo < b < hi and abs(x - b) <= TOL_CRITICAL * abs(b) else 0.0


def _rises_to(d1: Sequence[float], n: int, a: float, b: float) -> bool:
    """C rises_to: p certainly rises on (a, b) (p' at the middle beyond its rounding), so the
    critical point b is a maximum of p > 0 -- the farthest pass, never a touch."""
    m = a + 0.5 * (b - a)
    k = _scale_exponent(m, n - 1)
    v = horner(d1, n - 1, m, k, False)
    return v > 0 and not v <= noise_factor(n - 1) * _horner_abs(d1, n - 1, m, k)


def _scan_pieces(c: Sequence[float], d: list[list[float]], n: int, lo: float, T: float,
                 crit: list[float], skin: float, touch: float | None = None):
    """C scan_pieces: the first root in (lo, T] of c (c(lo) > 0), given its critical points
    there (ascending) and p', p'' in d[n - 1], d[n - 2]: monotone pieces scanned left to right,
    with the graze check at each critical point.  touch: on a touch's interval (C's tv), its
    critical point, a minimum by _touch_critical (no rises_to there, as in C)."""
    nc = len(crit)
    a, sa, sb, sb_known = lo, 1, 0, False
    for j in range(nc + 1):
        b = crit[j] if j < nc else T
        if not sb_known:
            sb = _sign_at(c, n, b, True)
        sb_known = False
        if sb == 0:
            return b, j < nc
        # at a critical point the fma sign may be noise (a touch): the precise value decides
        # whether p crosses in (a, b] (where b needs no scaling); so at the window's end when
        # p is within its noise there (C says why)
        precise = sb != sa and _scale_exponent(b, n) == 0 and (j < nc or _within_noise(c, n, b, 0.0))
        pb = _horner_compensated(c, n, b) if precise else 0.0
        if precise and pb != 0 and (pb > 0) == (sa > 0):
            sb = sa  # no crossing in (a, b]: maybe a touch at b (below)
        if sb != sa:
            if precise and j < nc:
                return _crossing_before_critical(c, d, n, a, b, sa, pb), False
            return _refine_root(c, d[n - 1], n, a, b, sa, 0.0, _split_point(a, b)), False
        # (a maximum is no touch; on a touch's interval b is a minimum: _touch_critical)
        if skin >= 0 and j < nc and _within_noise(c, n, b, skin) and not (
                touch is None and _rises_to(d[n - 1], n, a, b)):
            b2 = crit[j + 1] if j + 1 < nc else T
            sb = _sign_at(c, n, b2, True)
            sb_known = True
            # (its sign too is noise where p is within its noise there: the precise value
            # decides, as above)
            if sb != sa and _scale_exponent(b2, n) == 0 and _within_noise(c, n, b2, 0.0):
                p2 = _horner_compensated(c, n, b2)
                if p2 != 0 and (p2 > 0) == (sa > 0):
                    return _touch_point(d, n, b), True
            if sb == sa:
                return _touch_point(d, n, b), True
        a = b
    return None


def first_root_interval(p: Sequence[float], n: int, T: float, skin: float,
                        failed_w: float) -> tuple[float, bool, bool] | None:
    """First root in (0, T] of p (degree n >= 3, normalised, p[0] > 0: normalise's sign), as
    (t, graze, scanned): scanned where the derivative method found it (its scan's fma signs
    cannot see a crossing pair inside the noise: never_late looks again); failed_w: the window
    step 0b's test failed on, 0 if none (_isolate_first_root)."""
    lo = 0.0
    if T <= (FAST_LIMIT_LOW if n <= 8 else FAST_LIMIT_HIGH):
        r = _isolate_first_root(p, n, skin, T, failed_w)
        if r is _CLEARED:
            return None
        if isinstance(r, tuple):
            return r
        lo = r
    hit = _derivative_method(p, n, lo, T, 0.0, skin)
    return None if hit is None else (*hit, True)


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
                      nograze: bool) -> tuple[float, bool] | None:
    """Coefficients spanning more than 2^MAX_SPREAD (c[0] != 0, not normalised), slice by
    slice of t: the C runtime's first_root_sliced."""
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
        q = [_ldexp(c[i], k * i - top - 1) if nz[i] else 0.0 for i in range(n + 1)]
        q = [x if abs(x) >= DBL_MIN else 0.0 for x in q]
        m = n
        while m > 0 and q[m] == 0:
            m -= 1
        if m > 0:
            tu = _ldexp(tmax, -k)
            T = tu if tu < _HI else _HI
            skin = -1.0 if nograze else 0.0 if eps == 0 else _ldexp(eps, -top - 1)
            hit: tuple[float, bool] | None
            if m == 1:
                r = _div(-q[0], q[1])
                hit = (r, False) if _LO_OPEN < r <= T else None
            elif m == 2:
                hit = first_root_quadratic(q, T, skin, _LO_OPEN)
            else:
                s = _sign_at(q, m, _LO, True)
                if s < 0:
                    q = [-x for x in q]
                hit = (_LO, False) if s == 0 else _derivative_method(q, m, _LO, T, 0.0, skin)
            if hit is not None:
                # a root at or above half the least subnormal rounds up to it (C says why)
                t = _ldexp(hit[0], k)
                if t == 0 and hit[0] >= _ldexp(1.0, -1075 - k):
                    t = TRUE_MIN
                return t, hit[1]
        d += SLICE
    return None
