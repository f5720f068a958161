"""Smallest root in (0, tmax] of a real polynomial of degree <= 8, pure Python.

The same algorithm and contract as the C runtime (runtime/c/max2code_roots.h,
whose header comment is the reference); the differences are only where
Python 3.11 lacks a primitive:

* no ``math.fma``: Horner uses a multiply and an add (the graze bound,
  gamma_{2n}, is written for exactly that), and the quadratic's exact
  product errors come from Dekker's two-product (Veltkamp splitting) --
  exact, so the discriminant equals the C one bit for bit;
* results can therefore differ from C in the last ulp.
"""
from __future__ import annotations

import math
from typing import Sequence

MAX_DEGREE = 8
UNIT_ROUNDOFF = 2.0**-53
EPS = 2.0**-52
SAFE = 2.0**120  # |x| <= SAFE: Horner on normalised coefficients cannot overflow
MAX_ITER = 200  # geometric bisection: ~11 steps to a factor-2 bracket, <= 53 more
REAL_TOL = math.sqrt(EPS)  # |imag| <= REAL_TOL |z| counts as real (closed method)

Coeffs = list[float]


def ilogb(x: float) -> int:
    """Exponent e with 2^e <= |x| < 2^(e+1) (x != 0, finite)."""
    return math.frexp(x)[1] - 1


# ---------------------------------------------------------------------------
# Validation and preparation
# ---------------------------------------------------------------------------


def is_valid(c: Sequence[float], tmax: float) -> bool:
    """Degree 0..8, finite coefficients, tmax > 0 (may be +inf)."""
    if not 1 <= len(c) <= MAX_DEGREE + 1:
        return False
    if math.isnan(tmax) or tmax <= 0:
        return False
    return all(math.isfinite(x) for x in c)


def _ceil_div(num: int, den: int) -> int:
    return -((-num) // den)


def root_bound(c: Sequence[float], n: int) -> float:
    """Fujiwara bound 2 max |c_i/c_n|^(1/(n-i)), each term rounded up to a
    power of two from exponents alone (no overflow, no logs); every root is
    strictly below it.  0 when all lower coefficients are 0."""
    en = ilogb(c[n])
    best = None
    for i in range(n):
        if c[i] != 0:
            e = _ceil_div(ilogb(c[i]) + 1 - en, n - i)
            best = e if best is None or e > best else best
    if best is None:
        return 0.0
    if best + 1 >= 1024:
        return 1.7976931348623157e308
    return math.ldexp(1.0, best + 1)


def leading_negligible(c: Sequence[float], n: int, tmax: float) -> bool:
    """|c_n| T^n <= 4 n eps max_{i<n} |c_i| T^i over the window [0, T]; T is
    tmax, or when that is infinite the root bound of c_0..c_{n-1}.  Compared
    term by term as |c_n| T^(n-i) <= k |c_i| so overflow is harmless."""
    T = tmax
    if math.isinf(T):
        m = n - 1
        while m > 0 and c[m] == 0:
            m -= 1
        if m == 0:
            return False  # the rest is a constant: no scale to compare with
        T = root_bound(c, m)
    k = 4.0 * n * EPS
    Tp = 1.0
    for i in range(n - 1, -1, -1):
        Tp *= T  # T^(n-i); float overflow gives inf, underflow 0: both right
        if c[i] != 0 and abs(c[n]) * Tp <= k * abs(c[i]):
            return True
    return False


def reduce(c: Coeffs, tmax: float) -> int:
    """Drop zero or negligible leading terms and factors of t (the bodies
    touch now; the next root strictly after 0 is wanted).  Works in place;
    returns the degree left, or -1 for the zero polynomial."""
    n = len(c) - 1
    while True:
        while n > 0 and c[n] == 0:
            n -= 1
        if n == 0:
            return -1 if c[0] == 0 else 0
        if c[0] == 0:
            del c[0]
            c.append(0.0)
            n -= 1
            continue
        if leading_negligible(c, n, tmax):
            c[n] = 0.0
            n -= 1
            continue
        return n


def normalise(c: Coeffs, n: int) -> None:
    """Scale by a power of two (exact) so that max |c_i| is in [1/2, 1)."""
    m = max(abs(x) for x in c[: n + 1])
    if m != 0:
        e = ilogb(m) + 1
        for i in range(n + 1):
            c[i] = math.ldexp(c[i], -e)


# ---------------------------------------------------------------------------
# Evaluation
# ---------------------------------------------------------------------------


def scale_exponent(x: float) -> int:
    """k such that evaluating at x / 2^k cannot overflow."""
    return 0 if abs(x) <= SAFE else ilogb(x) + 1


def horner(c: Sequence[float], n: int, x: float, k: int) -> float:
    """p(x) / 2^(k n); with k != 0 argument and coefficients are scaled by
    exact powers of two so that roots near 1e154 evaluate without overflow."""
    acc = c[n]
    if k == 0:
        for i in range(n - 1, -1, -1):
            acc = acc * x + c[i]
        return acc
    xs, f, fi = math.ldexp(x, -k), math.ldexp(1.0, -k), 1.0
    for i in range(n - 1, -1, -1):
        fi *= f
        acc = acc * xs + c[i] * fi
    return acc


def horner_abs(c: Sequence[float], n: int, x: float, k: int) -> float:
    """sum |c_i| |x|^i / 2^(k n): the scale of Horner's rounding error."""
    ax = abs(x)
    xs, f, fi = (math.ldexp(ax, -k) if k else ax), math.ldexp(1.0, -k), 1.0
    acc = abs(c[n])
    for i in range(n - 1, -1, -1):
        fi *= f
        acc = acc * xs + abs(c[i]) * fi
    return acc


def within_noise(c: Sequence[float], n: int, x: float) -> bool:
    """|p(x)| <= 2 gamma_{2n} sum |c_i| |x|^i: p(x) is zero within the
    rounding error of evaluating it (factor 2 for safety)."""
    k = scale_exponent(x)
    g = 2 * n * UNIT_ROUNDOFF / (1 - 2 * n * UNIT_ROUNDOFF)
    return abs(horner(c, n, x, k)) <= 2 * g * horner_abs(c, n, x, k)


def sign_at(c: Sequence[float], n: int, x: float) -> int:
    v = horner(c, n, x, scale_exponent(x))
    return (v > 0) - (v < 0)


# ---------------------------------------------------------------------------
# Quadratic
# ---------------------------------------------------------------------------

_SPLIT = 134217729.0  # 2^27 + 1


def _two_product_error(a: float, b: float, p: float) -> float:
    """Exact a*b - p for p = fl(a*b) (Dekker), what fma(a, b, -p) gives."""
    t = _SPLIT * a
    ah = t - (t - a)
    al = a - ah
    t = _SPLIT * b
    bh = t - (t - b)
    bl = b - bh
    return ((ah * bh - p) + ah * bl + al * bh) + al * bl


def quad_roots(a: float, b: float, c: float) -> tuple[list[float], float]:
    """Real roots (ascending, two of them, or none) of a x^2 + b x + c,
    a != 0, and the discriminant (exactly 0 for a double root).

    With h = -b/2 the roots are (h +- sqrt(h^2 - a c)) / a.  h^2 - a c is
    (p - q) + (dp - dq) with dp, dq the exact errors of p = h*h, q = a*c:
    when p and q nearly cancel, p - q is exact and the corrections carry the
    digits (Kahan's case).  Coefficients are scaled by a power of two first
    so h*h cannot overflow; the larger root avoids cancellation and the
    other comes from the product of the roots."""
    e = ilogb(max(abs(a), abs(b), abs(c)))
    a, b, c = math.ldexp(a, -e), math.ldexp(b, -e), math.ldexp(c, -e)
    h = -0.5 * b
    p, q = h * h, a * c
    d = (p - q) + (_two_product_error(h, h, p) - _two_product_error(a, c, q))
    if d < 0:
        return [], d
    w = h + math.copysign(math.sqrt(d), h)
    if w == 0:  # h == 0 and d == 0, so c == 0: double root at 0
        return [0.0, 0.0], d
    r1, r2 = w / a, c / w
    return sorted((r1, r2)), d


def first_root_quadratic(c: Sequence[float], tmax: float, graze_check: bool) -> tuple[float, bool] | None:
    """First root in (0, tmax] of c0 + c1 t + c2 t^2 (c2 != 0)."""
    roots, disc = quad_roots(c[2], c[1], c[0])
    for r in roots:
        if 0 < r <= tmax:
            return r, disc == 0
    if roots or not graze_check:
        return None
    x = -c[1] / (2 * c[2])  # vertex: does the parabola touch 0 within rounding?
    if 0 < x <= tmax and within_noise(c, 2, x):
        return x, True
    return None


# ---------------------------------------------------------------------------
# Safeguarded Newton on a monotone bracket
# ---------------------------------------------------------------------------


def split_point(lo: float, hi: float) -> float:
    """Bisection point; geometric when the bracket spans more than a factor
    8, so roots near 0 come out to relative, not absolute, accuracy."""
    if lo == 0:
        return hi * 2.0**-10
    if hi > 8 * lo:
        return math.sqrt(lo) * math.sqrt(hi)
    return lo + 0.5 * (hi - lo)


def refine_root(P: Sequence[float], D: Sequence[float], m: int, lo: float, hi: float, slo: int) -> float:
    """Root of P (degree m, derivative D) in (lo, hi), where P is monotone and
    changes sign (slo = sign of P(lo)).  Newton, replaced by bisection when
    the step leaves the bracket or fails to halve the step before last."""
    x = split_point(lo, hi)
    step = step_old = hi - lo
    for _ in range(MAX_ITER):
        k = scale_exponent(x)
        f = horner(P, m, x, k)
        if f == 0:
            return x
        if (f > 0) == (slo > 0):
            lo = x
        else:
            hi = x
        if hi - lo <= 2 * EPS * hi:
            return x
        df = horner(D, m - 1, x, k)
        try:
            xn = x - math.ldexp(f / df, k)
        except (ZeroDivisionError, OverflowError):
            xn = math.nan
        s = x - xn
        if not (lo < xn < hi) or abs(s) > 0.5 * abs(step_old):
            xn = split_point(lo, hi)
            s = x - xn
        step_old, step = step, s
        if abs(s) <= 2 * UNIT_ROUNDOFF * abs(xn):
            return xn
        x = xn
    return x


# ---------------------------------------------------------------------------
# Interval solver
# ---------------------------------------------------------------------------


def derivative_chain(c: Sequence[float], n: int) -> list[list[float]]:
    """d[m] = derivative of order n - m, of degree m (d[0], d[1] unused)."""
    d: list[list[float]] = [[] for _ in range(n + 1)]
    d[n] = list(c[: n + 1])
    for m in range(n, 1, -1):
        d[m - 1] = [(i + 1) * d[m][i + 1] for i in range(m)]
    return d


def roots_in_pieces(P: Sequence[float], D: Sequence[float], m: int, crit: Sequence[float], T: float) -> list[float]:
    """Roots in (0, T) of P (degree m), monotone between the ascending
    critical points crit."""
    out = []
    a, sa = 0.0, sign_at(P, m, 0.0)
    for j in range(len(crit) + 1):
        b = crit[j] if j < len(crit) else T
        sb = sign_at(P, m, b)
        if sb == 0:
            if j < len(crit):
                out.append(b)
        elif sa != 0 and sa != sb:
            out.append(refine_root(P, D, m, a, b, sa))
        a, sa = b, sb
    return out


def critical_points(d: list[list[float]], n: int, T: float) -> list[float]:
    """Roots in (0, T) of d[n]'s derivative, level by level from the
    quadratic derivative up."""
    roots, _ = quad_roots(d[2][2], d[2][1], d[2][0])
    level: list[float] = []
    for r in roots:
        if 0 < r < T and (not level or r > level[-1]):
            level.append(r)
    for m in range(3, n):
        level = roots_in_pieces(d[m], d[m - 1], m, level, T)
    return level


def first_root_interval(c: Sequence[float], n: int, T: float, graze_check: bool) -> tuple[float, bool] | None:
    """First root in (0, T] of c (degree >= 3, normalised, c[0] != 0)."""
    d = derivative_chain(c, n)
    crit = critical_points(d, n, T)
    nc = len(crit)
    a, sa = 0.0, (1 if c[0] > 0 else -1)
    cached: int | None = None
    for j in range(nc + 1):
        b = crit[j] if j < nc else T
        sb = cached if cached is not None else sign_at(c, n, b)
        cached = None
        if sb == 0:  # exact zero: at a critical point it is a double root
            return b, j < nc
        if sb != sa:
            return refine_root(c, d[n - 1], n, a, b, sa), False
        if graze_check and j < nc and within_noise(c, n, b):
            b2 = crit[j + 1] if j + 1 < nc else T
            cached = sign_at(c, n, b2)  # touch (same sign beyond) or cross?
            if cached == sa:
                return b, True
        a = b
    return None
