"""Never later than the first root: the rounding-band certificates
(C: ``runtime/c/roots/never_late.inc``)."""

from __future__ import annotations

import math
from typing import Sequence

from .shared import MAX_SPREAD, U, fma, ilogb, ldexp
from .prepare import exponents, normalise
from .evaluate import horner_abs, noise_factor, scale_exponent, sign_at, within_noise
from .newton import horner_compensated
from .derivative import half_curvature_floor, noise_chains
from .interval import first_root_interval


def _band_side(c: Sequence[float], n: int, tail: Sequence[float], x: float) -> int:
    """C band_side: 1 where p(x) > 0 certainly, -1 where p(x) < 0 certainly, 0 within the
    rounding band, for p = c_0..c_n plus the terms reduce dropped, tail[j] x^(n+1+j): p's own
    by compensated Horner, the tail's by plain Horner, each within its error bound, taken
    twice."""
    g = 0.5 * noise_factor(n)  # gamma_{2n}
    v = horner_compensated(c, n, x)
    a = horner_abs(c, n, x, 0)
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


def _positive_through_the_noise(c: Sequence[float], n: int, r: float) -> bool:
    """C positive_through_the_noise: p certainly positive on [r - h, r] and above the fma noise
    at r - h (Taylor's bound from Horner's chains at r; the C source has it)."""
    f, gs = noise_chains(c, n, r, r)
    (_, f1, f2, _), (g0, g1, *_) = f, gs
    e, rel = noise_factor(n), 4.0 * (n + 1) * U
    g = 0.5 * e
    v = horner_compensated(c, n, r)
    m = v - 2 * (U * abs(v) + g * g * g0)  # p(r) >= m
    S = (abs(f1) + e * g1) * (1 + rel)  # >= |p'(r)|
    N = e * g0 * (1 + rel)  # >= the fma noise anywhere in [0, r]
    if not (m > 0 and f2 > 0):
        return False
    h = (S + math.sqrt(S * S + 4 * f2 * N)) / f2
    L = half_curvature_floor(f, gs, e, rel, h)
    return (h < r and L > 0 and S * S < 4 * L * m * (1 - rel)
            and (m - S * h + L * h * h) * (1 - rel) > N)


def _falls_through_the_noise(c: Sequence[float], n: int, r: float) -> bool:
    """C falls_through_the_noise: p' certainly negative on [r - h, r] and p above the fma noise
    at r - h, so no crossing pair hides in the noise to the left of the crossing r (Taylor's
    bounds from Horner's chains at r, signed; the C source has it)."""
    f, gs = noise_chains(c, n, r, r)
    (f0, f1, f2, _), (g0, g1, *_) = f, gs
    e, rel = noise_factor(n), 4.0 * (n + 1) * U
    N = e * g0 * (1 + rel)  # >= the fma noise anywhere in [0, r]
    m = f0 - N  # p(r) >= m (the chain's own noise)
    D = -(f1 + e * g1) * (1 - rel)  # <= -p'(r)
    if not (D > 0 and N > m):
        return False
    k = f2 if f2 > 0 else 0.0
    h = 4 * (N - m) / (D + math.sqrt(D * D + 4 * k * (N - m)))
    L = half_curvature_floor(f, gs, e, rel, h)
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
    if scale_exponent(r, n) != 0 or certified(c, n, r):
        return hit
    step = r * 2.0**-50
    while True:
        step *= 2
        xb = r - step
        if not xb > 0 or step > r * 2.0**-4:
            return hit
        if not within_noise(c, n, xb, 0.0):
            break
    if not sign_at(c, n, xb, True) > 0:
        return hit  # (left to the steps of never_late's caller: not a near miss)
    w = r - xb
    e = ilogb(w) + 1
    q = _shift_dd(c, n, xb, ldexp(1.0, e))
    _, _, spread, emax = exponents(q, n)
    if not q[0] > 0 or spread > MAX_SPREAD:
        return hit
    normalise(q, n, emax, 1.0)
    T = ldexp(w, -e)
    found = first_root_interval(q, n, T, 0.0, 0.0)
    if found is None:
        return hit
    t, gu = xb + ldexp(found[0], e), found[1]
    if not t < r:
        return hit
    # q's doubles are p shifted and rounded once: near a cluster that moves q's roots by far
    # more than p's own band (INSIDE_THE_NOISE's fourth vector: 2.1e-13 late), so t is held to
    # p's compensated band as never_late holds a root (no second look inside the noise).
    d = t * 2.0**-50
    hs = _band_side(c, n, [], t if gu else t - d)
    if (hs == -1 or (hs == 0 and _band_side(c, n, [], t - d) != 1)) if gu else (hs != 1):
        return _band_walk(c, n, [], t, d, hs, gu)
    return t, gu


def never_late(c: Sequence[float], n: int, tail: Sequence[float], hit: tuple[float, bool]
               ) -> tuple[float, bool]:
    """C never_late (issue 33, item 11): never later than the first root of the polynomial as
    given (c and the dropped terms, tail).  A root or a touch stands where p is certainly
    positive just before it, at r (1 - 2^-50), a touch also where p is certainly positive at it
    (a near miss, looked at again inside the noise); else (inside the band: a rounded multiple
    root's exact first root may lie anywhere in it before r) the earliest point that cannot be
    excluded (steps to the left, doubling, then bisection): a crossing where p is certainly
    negative there, else a touch."""
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
    if hs == 1 or (g and hs == 0 and _band_side(c, n, tail, before) == 1):
        return hit  # p certainly positive before it, or at a touch (a near miss)
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


def late_sliced_tail(q: Sequence[float], m: int, n: int, dropped: Sequence[float], k: int,
                     top: int, sign: float, hit: tuple[float, bool]) -> tuple[float, bool]:
    """C late_sliced_tail: never_late on a slice where reduce dropped leading terms: q (degree
    m) is c_i 2^(k i - top - 1) times sign, its terms of degrees m+1..n 0 in the tail, the
    dropped ones scaled alike after them."""
    tail = [0.0] * (n - m) + [ldexp(sign * v, k * (n + 1 + j) - top - 1)
                              for j, v in enumerate(dropped)]
    return never_late(q, m, tail, hit)


def late_low_degree(c: Sequence[float], n: int, tail: Sequence[float], hit: tuple[float, bool]
                    ) -> tuple[float, bool]:
    """C late_low_degree: never_late for the closed forms of degree 1 and 2 after reduce dropped
    leading terms (tail, scaled as c), with p(0) made positive, as never_late wants."""
    s = -1.0 if c[0] < 0 else 1.0
    return never_late([s * v for v in c[:n + 1]], n, [s * v for v in tail], hit)


def dropped_terms(cc: Sequence[float], n: int) -> list[float]:
    """C dropped_terms: the leading terms reduce dropped from cc (n kept after the factors of t
    it divided out), up to the last nonzero; empty where it dropped none."""
    low = next(i for i, v in enumerate(cc) if v != 0)
    top = max(max(i for i, v in enumerate(cc) if v != 0), low + n)
    return list(cc[low + n + 1:top + 1])
