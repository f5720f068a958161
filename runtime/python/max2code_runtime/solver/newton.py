"""Compensated Horner and safeguarded Newton (C: ``runtime/c/roots/newton.inc``)."""

from __future__ import annotations

import math
from typing import Sequence

from .shared import DBL_MIN, EPS, MAX_ITER, NOISE_STEP, PRECISE_FROM, SLOW_AFTER, U, div, ldexp
from .evaluate import horner, horner_abs, noise_factor, scale_exponent


def split_point(lo: float, hi: float) -> float:
    if lo == 0:
        return hi * 2.0**-10
    if hi > 8 * lo:
        return math.sqrt(lo) * math.sqrt(hi)
    return lo + 0.5 * (hi - lo)


def horner_compensated(P: Sequence[float], m: int, x: float) -> float:
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


def value_and_slope(P: Sequence[float], D: Sequence[float], m: int, x: float, k: int,
                     precise: bool) -> tuple[float, float, float]:
    """C value_and_slope; one call per Newton step of refine_root (where C counts one, so the
    control-flow test wraps it)."""
    if k != 0:
        return horner(P, m, x, k, precise), horner(D, m - 1, x, k, False), horner_abs(P, m, x, k)
    f, df, ax, sz = P[m], D[m - 1], abs(x), abs(P[m])
    f = f * x + P[m - 1]
    sz = sz * ax + abs(P[m - 1])
    for i in range(m - 2, -1, -1):
        df = df * x + D[i]
        sz = sz * ax + abs(P[i])
        f = f * x + P[i]
    return (horner_compensated(P, m, x) if precise else f), df, sz


# C PRECISE_NOW: refine_root's tol for an x0 already converged (the guess's Laguerre iterate):
# full accuracy, precise from the first step
PRECISE_NOW = -1.0


def refine_root(P: Sequence[float], D: Sequence[float], m: int, lo: float, hi: float, slo: int,
                 tol: float, x0: float) -> float:
    x = x0
    step = step_old = hi - lo
    precise = tol < 0  # PRECISE_NOW: x0 converged, precise from the first step
    tol = 0.0 if tol < 0 else tol
    stop = tol if tol > 0 else 2 * U if precise else PRECISE_FROM
    for it in range(MAX_ITER):
        k = scale_exponent(x, m)
        f, df, size = value_and_slope(P, D, m, x, k, precise)
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
        xn = x - (ldexp(div(f, df), k) if k else div(f, df))
        s = x - xn
        slow = it >= SLOW_AFTER and (lo == 0 or hi > 8 * lo) and abs(s) > 2.0**-10 * abs(xn)
        if not (lo < xn < hi) or abs(s) > 0.5 * abs(step_old) or slow:
            # (with tol > 0 too: a step in the noise that a noisy sign pushed out of the
            # bracket; bisecting from there crept to tol, see C refine_root)
            if (precise or tol > 0) and abs(s) <= NOISE_STEP * abs(x):
                return x
            far = hi * 2.0**-64
            xn = far if slow and lo == 0 and far > DBL_MIN else split_point(lo, hi)
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
