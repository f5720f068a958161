"""Budan-Fourier isolation: Laguerre's guess and the bisection
(C: ``runtime/c/roots/isolate.inc``)."""

from __future__ import annotations

import math
from typing import NamedTuple, Sequence

from .shared import (EARLY_WIDTH, GUESS_DONE, GUESS_FAST, MAX_SPLITS, MIN_WIDTH, PRECISE_FROM,
                     SPLIT_NEWTON, div)
from .evaluate import horner_abs, noise_factor
from .newton import PRECISE_NOW, refine_root, split_point
from .bernstein import (BERN_CLEAR, BERN_ONE, BINOM, DIP_INSIDE, bernstein_clear,
                        bernstein_test, clearly_positive, derivative, point_at, point_at_zero)
from .derivative import derivative_method, scan_pieces, touch_critical


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


def laguerre_terms(p: Sequence[float], n: int, x: float) -> tuple[float, float, float]:
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


def speculate_first_root(p: Sequence[float], n: int, T: float) -> _Guess:
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
    overflows to inf as C's does; the step's denominator and s / last may be 0 (div gives C's
    inf or NaN), and the test of u comes before sqrt, which raises on a negative argument where
    C's would give NaN."""
    x = last = qprev = xprev = dip = 0.0  # dip: C's *dip, set wherever the guess saw one
    critical = steady = 0  # Newton on p' (after the double-root signature)
    newton = 0  # Newton steps in Laguerre's place
    for it in range(SPECULATE_STEPS + TOUCH_EXTRA + TOUCH_STEPS):
        if not critical and it >= SPECULATE_STEPS and (
                steady == 0 or it >= SPECULATE_STEPS + TOUCH_EXTRA):
            return _Guess(None, 0.0, dip)
        f, d1, d2 = laguerre_terms(p, n, x)
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
                near = abs(f) <= TOUCH_NEAR * noise_factor(n) * horner_abs(p, n, x, 0)
                return _Guess(None, x, dip) if near else _Guess(None, 0.0, x)  # (else a dip)
            if critical > 1 and not (abs(s) <= 0.5 * abs(last)):
                return _Guess(None, 0.0, dip)
            critical += 1
            last = s
            continue
        if f == 0:
            return _Guess(x if x > 0 else None, 0.0, dip)
        if f < 0:  # past a root: one in (xprev, x); Newton from x if it stays inside
            y = x - div(f, d1)
            return _Guess(y if xprev < y < x else xprev + 0.5 * (x - xprev), 0.0, dip, x)
        # (n - 1) f^2 times Laguerre's discriminant: its sign, and the step from one division
        u = (n - 1) * (d1 * d1) - 2 * n * (f * d2)
        if not (u >= 0):
            # complex roots in the way (or NaN): Newton on p' towards the dip, and in
            # Laguerre's place, up to GUESS_NEWTON times while p falls, a Newton step
            if d2 > 0:
                dip = x - div(d1, 2 * d2)
            if newton == GUESS_NEWTON or not (d1 < 0):
                return _Guess(None, 0.0, dip)
            newton += 1
            s = f / d1
        else:
            s = div(n * f, d1 - math.copysign(math.sqrt((n - 1) * u), f))  # to the right: < 0
        if not (s < 0):
            return _Guess(None, 0.0, dip)
        xprev = x
        x -= s
        if not (x > 0 and x < T):
            return _Guess(None, 0.0, dip)
        q = div(s, last) if it > 0 else 0.0
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


def _polish_isolated(p: Sequence[float], n: int, a: float, b: float, pa: float,
                     pb: float) -> float:
    """The one simple root of p in (a, b), p(a) = pa > 0 > pb = p(b): safeguarded Newton from
    the regula falsi point (C polish_isolated)."""
    dp = derivative(p, n)
    x0 = a + (b - a) * div(pa, pa - pb)
    if not (a < x0 < b):
        x0 = split_point(a, b)
    return refine_root(p, dp, n, a, b, 1, 0.0, x0)


def _isolation_split(a: float, b: float) -> float:
    if a == 0:
        return b * 0.0625
    if b > 8 * a:
        return math.sqrt(a) * math.sqrt(b)
    return a + 0.5 * (b - a)


CLEARED = object()


def isolate_first_root(p: Sequence[float], n: int, skin: float, T: float, failed_w: float):
    """(t, graze, scanned), CLEARED, or a float: the left end left to the derivative method
    (scanned: the hit is its, first_root_interval).  failed_w:
    the window step 0b's test failed on (cleared_at_once; 0 when not tried), whose first
    clearly_positive is that very test when T equals it: skipped then, as C does."""
    e = noise_factor(n) if skin >= 0 else 0.0
    sk = skin if skin > 0 else 0.0
    a = point_at_zero(p, n, e, sk)
    if not (a.qt[0] - a.tol[0] > 0):
        return 0.0
    # Descartes, or q(0) beats every negative term (unless that very test failed already)
    if a.vq == 0 or (T != failed_w and clearly_positive(a, n, T, 1)):
        return CLEARED
    # A guess first, then a certificate: the guess (Laguerre from 0) and one Bernstein test on
    # (0, r (1 + 2^-20)] settle most solves with a root, which the test on the whole window
    # before them only delayed (measured: see the C source).
    guess = speculate_first_root(p, n, T)
    r = guess.root
    if r is not None:
        end = guess.over if guess.over > 0 else r  # (overshot: up to the step's end)
        w = end + end * SPECULATE_MARGIN
        w = w if w < T else T
        if bernstein_test(a, n, w, False).answer == BERN_ONE:
            tol = 0.0 if guess.over > 0 else PRECISE_NOW
            return refine_root(p, derivative(p, n), n, 0.0, w, 1, tol, r), False, False
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
        if bernstein_test(a, n, lo, False).answer == BERN_CLEAR:
            # p convex around the touch, its critical point certified in one pass
            # (touch_critical), else the derivative method (see the C source)
            d: list[list[float]] = [[] for _ in range(n)]  # rows n - 1, n - 2 only
            d[n - 1] = derivative(p, n)
            d[n - 2] = derivative(d[n - 1], n - 1)
            b = touch_critical(p, d, n, lo, hi, touch)
            hit = (scan_pieces(p, d, n, lo, hi, [b], skin, b) if b > 0 else
                   derivative_method(p, n, lo, hi, touch, skin))
            # (on (lo, hi], convex by touch_critical's certificate, p falls to b alone: no
            # crossing pair can hide there, not scanned)
            if hit is not None:
                return (*hit, not b > 0)
            if hi == T:
                return CLEARED
            frm = hi
    if frm == 0:  # the whole window, unless a touch's interval settled (0, frm]
        start = bernstein_test(a, n, T, True)
        if start.answer == BERN_CLEAR:
            return CLEARED
        if start.answer == BERN_ONE:
            return _polish_isolated(p, n, 0.0, T, a.px, start.pend), False, False
        q = start.q
        assert q is not None  # (asked for, and not cleared)
        if q.even and bernstein_clear(q, n, div(guess.dip, T)):  # (after a guess that failed)
            return CLEARED
    tk = [[BINOM[k][j] * p[j + k] if j + k <= n else 0.0 for j in range(n + 1)] for k in range(n + 1)]
    ta = [[abs(v) for v in row] for row in tk]
    first = point_at(tk, ta, e, sk, n, T)
    if first is None:
        return frm
    if frm > 0:  # the counts start from frm: its Point, q's sign there certain
        a = point_at(tk, ta, e, sk, n, frm)
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
        if a.vq == b.vq or (not odd and (clearly_positive(a, n, w, 1) or clearly_positive(b, n, w, -1))):
            a = stack.pop()
            tested = False
            if not stack:
                return CLEARED
            continue
        if a.vp - b.vp == 1 and a.vq - b.vq == 1:
            return _polish_isolated(p, n, a.x, b.x, a.px, b.px), False, False
        # Bernstein only for an odd count (a root certain), and not again on (0, T]
        if odd and not tested and bernstein_test(a, n, w, False).answer == BERN_ONE:
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
            mt = a.x + SPLIT_NEWTON * div(-a.px, a.dpx)
            hair = a.x + 4 * MIN_WIDTH * b.x
            if splits == 0 and a.x + DIP_INSIDE * w < guess.dip < b.x - DIP_INSIDE * w:
                m = guess.dip  # the first split where the failed guess saw p dip (C says why)
            elif a.dpx < 0 and a.x < mt < b.x and mt - a.x > MIN_WIDTH * b.x:
                m = mt
            elif a.dpx < 0 and mt > a.x and mt - a.x <= MIN_WIDTH * b.x and hair < b.x:
                m = hair
            if splits < MAX_SPLITS and w > MIN_WIDTH * b.x and a.x < m < b.x:
                pt = point_at(tk, ta, e, sk, n, m)
                if pt is not None:
                    splits += 1
                    stack.append(pt)
                    continue
        hit = derivative_method(p, n, a.x, b.x, 0.0, skin)
        if hit is not None:
            return (*hit, True)
        if not (b.qt[0] - b.tol[0] > 0):
            return b.x
        a = stack.pop()
        if not stack:
            return CLEARED
