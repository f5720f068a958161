"""The derivative (Yuksel) method, its scan, touches and their certificates
(C: ``runtime/c/roots/derivative.inc``)."""

from __future__ import annotations

import math
from typing import Sequence

from .shared import MAXN, NOISE_STEP, TOL_CRITICAL, TOL_LEVEL, U, div
from .evaluate import horner, horner_abs, noise_factor, scale_exponent, sign_at, within_noise
from .quadratic import quad_roots
from .newton import horner_compensated, refine_root, split_point, value_and_slope
from .bernstein import derivative


# ---------------------------------------------------------------------------
# Derivative method
# ---------------------------------------------------------------------------


def _derivative_chain(c: Sequence[float], n: int) -> list[list[float]]:
    d = [[0.0] * (MAXN + 1) for _ in range(n + 1)]
    d[n][: n + 1] = c[: n + 1]
    for m in range(n, 1, -1):
        d[m - 1][:m] = derivative(d[m], m)
    return d


def _roots_in_pieces(P, D, m: int, lo: float, crit: list[float], T: float, tol: float,
                     x0: float = 0.0) -> list[float]:
    out = []
    a = lo
    sa = sign_at(P, m, lo, False)
    for j in range(len(crit) + 1):
        b = crit[j] if j < len(crit) else T
        sb = sign_at(P, m, b, False)
        if sb == 0:
            if j < len(crit):
                out.append(b)
        elif sa != 0 and sa != sb:
            out.append(refine_root(P, D, m, a, b, sa, tol, x0 if a < x0 < b else split_point(a, b)))
        a, sa = b, sb
    return out


def _convex_on(d: list[list[float]], n: int, lo: float, T: float) -> bool:
    """C convex_on: p'' certainly positive on [lo, T], beyond the rounding of its plain Horner
    value anywhere there (the C source has the bound); then the level for the roots of p'' is
    empty whatever the levels below find, and the roots of p' come from an empty level."""
    if n < 4 or not lo >= 0 or scale_exponent(T, n) != 0:
        return False
    m = lo + 0.5 * (T - lo)
    h = m - lo if m - lo > T - m else T - m
    v = horner(d[n - 2], n - 2, m, 0, False)
    slope = horner_abs(d[n - 3], n - 3, T, 0)
    size = horner_abs(d[n - 2], n - 2, T, 0)
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
    x0 = split_point(a, b)
    h2 = div(-2 * pb, horner(d[n - 2], n - 2, b, 0, False))
    xq = b - math.sqrt(h2 if h2 > 0 else 0.0)
    if a < xq < b:
        x0 = xq
    return refine_root(c, d[n - 1], n, a, b, sa, 0.0, x0)


def _touch_point(d: list[list[float]], n: int, b: float) -> float:
    """C touch_point: where a touch is reported -- the critical point b, which plain Newton on
    p' leaves anywhere within p''s rounding noise, moved by one Newton step on p' evaluated
    precisely (compensated), kept only when that step is within the noise too (b unscaled)."""
    if scale_exponent(b, n - 1) != 0:
        return b
    v, slope, _ = value_and_slope(d[n - 1], d[n - 2], n - 1, b, 0, True)
    x = b - div(v, slope)
    return x if abs(x - b) <= NOISE_STEP * abs(b) else b


def derivative_method(c: Sequence[float], n: int, lo: float, T: float, x0: float, skin: float):
    """C derivative_method: the critical points in (lo, T), then scan_pieces."""
    d = _derivative_chain(c, n)
    return scan_pieces(c, d, n, lo, T, _critical_points(d, n, lo, T, x0), skin)


def touch_critical(p: Sequence[float], d: list[list[float]], n: int, lo: float, hi: float,
                    x: float) -> float:
    """C touch_critical: the critical point of p in (lo, hi) around the guess's touch x,
    certified in one pass (p convex on [lo, hi], p' < 0 at lo and > 0 at hi, from Horner's
    chains for p', p''/2, p'''/6 at x and bounds at hi; the C source has the bound), found as
    the derivative method finds it (its first Newton step on p' from x, ending there within
    TOL_CRITICAL); 0 where the pass cannot tell.  d[n - 1], d[n - 2]: p', p''."""
    # (a bracket below TOL_CRITICAL would end refine_root before its step: left to it)
    if not (lo >= 0 and lo < x and hi - x > TOL_CRITICAL * hi) or scale_exponent(hi, n) != 0:
        return 0.0
    f, g = noise_chains(p, n, x, hi)
    e, rel = noise_factor(n), 4.0 * (n + 1) * U
    h = x - lo if x - lo > hi - x else hi - x
    L = half_curvature_floor(f, g, e, rel, h)
    slope = (abs(f[1]) + e * g[1]) * (1 + rel)  # >= |p'(x)|
    if not (L > 0 and slope < 2 * L * (x - lo) * (1 - rel) and slope < 2 * L * (hi - x) * (1 - rel)):
        return 0.0
    # refine_root's first step on p' from x (tol TOL_CRITICAL), and its stop
    v, df, _ = value_and_slope(d[n - 1], d[n - 2], n - 1, x, 0, False)
    if v == 0:
        return x
    b = x - div(v, df)
    return b if lo < b < hi and abs(x - b) <= TOL_CRITICAL * abs(b) else 0.0


def _rises_to(d1: Sequence[float], n: int, a: float, b: float) -> bool:
    """C rises_to: p certainly rises on (a, b) (p' at the middle beyond its rounding), so the
    critical point b is a maximum of p > 0 -- the farthest pass, never a touch."""
    m = a + 0.5 * (b - a)
    k = scale_exponent(m, n - 1)
    v = horner(d1, n - 1, m, k, False)
    return v > 0 and not v <= noise_factor(n - 1) * horner_abs(d1, n - 1, m, k)


def scan_pieces(c: Sequence[float], d: list[list[float]], n: int, lo: float, T: float,
                 crit: list[float], skin: float, touch: float | None = None):
    """C scan_pieces: the first root in (lo, T] of c (c(lo) > 0), given its critical points
    there (ascending) and p', p'' in d[n - 1], d[n - 2]: monotone pieces scanned left to right,
    with the graze check at each critical point.  touch: on a touch's interval (C's tv), its
    critical point, a minimum by touch_critical (no rises_to there, as in C)."""
    nc = len(crit)
    a, sa, sb, sb_known = lo, 1, 0, False
    for j in range(nc + 1):
        b = crit[j] if j < nc else T
        if not sb_known:
            sb = sign_at(c, n, b, True)
        sb_known = False
        if sb == 0:
            return b, j < nc
        # at a critical point the fma sign may be noise (a touch): the precise value decides
        # whether p crosses in (a, b] (where b needs no scaling); so at the window's end when
        # p is within its noise there (C says why)
        precise = sb != sa and scale_exponent(b, n) == 0 and (j < nc or within_noise(c, n, b, 0.0))
        pb = horner_compensated(c, n, b) if precise else 0.0
        if precise and pb != 0 and (pb > 0) == (sa > 0):
            sb = sa  # no crossing in (a, b]: maybe a touch at b (below)
        if sb != sa:
            if precise and j < nc:
                return _crossing_before_critical(c, d, n, a, b, sa, pb), False
            return refine_root(c, d[n - 1], n, a, b, sa, 0.0, split_point(a, b)), False
        # (a maximum is no touch; on a touch's interval b is a minimum: touch_critical)
        if skin >= 0 and j < nc and within_noise(c, n, b, skin) and not (
                touch is None and _rises_to(d[n - 1], n, a, b)):
            b2 = crit[j + 1] if j + 1 < nc else T
            sb = sign_at(c, n, b2, True)
            sb_known = True
            # (its sign too is noise where p is within its noise there: the precise value
            # decides, as above)
            if sb != sa and scale_exponent(b2, n) == 0 and within_noise(c, n, b2, 0.0):
                p2 = horner_compensated(c, n, b2)
                if p2 != 0 and (p2 > 0) == (sa > 0):
                    return _touch_point(d, n, b), True
            if sb == sa:
                return _touch_point(d, n, b), True
        a = b
    return None


def noise_chains(c: Sequence[float], n: int, x: float, y: float
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


def half_curvature_floor(f: Sequence[float], g: Sequence[float], e: float, rel: float,
                          h: float) -> float:
    """C half_curvature_floor: a lower bound of p''/2 over [x - h, x + h] within [-y, y], by
    Taylor from the chains at x (noise_chains)."""
    return f[2] * (1 - rel) - (e * g[2] + 3 * (abs(f[3]) + e * g[3]) * h + 6 * g[4] * h * h) * (1 + rel)
