"""Budan-Fourier points, the Taylor shifts and the Bernstein tests
(C: ``runtime/c/roots/bernstein.inc``)."""

from __future__ import annotations

import math
from typing import NamedTuple, Sequence

from .shared import DBL_MIN, EPS, MAXN, U, div


# ---------------------------------------------------------------------------
# Budan-Fourier isolation
# ---------------------------------------------------------------------------


def sign_changes(v: Sequence[float], n: int) -> int:
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


def point_at_zero(p: Sequence[float], n: int, e: float, skin: float) -> _Point:
    qt = [p[i] - e * abs(p[i]) for i in range(n + 1)]
    tol = [EPS * abs(p[i]) for i in range(n + 1)]
    vp = sign_changes(p, n)
    if skin > 0:
        qt[0] -= skin
        tol[0] += EPS * skin
        vq = sign_changes(qt, n)
    else:
        vq = vp
    return _Point(0.0, p[0], p[1], vp, vq, [p[i] for i in range(n + 1)], qt, tol)


def point_at(tk: list[list[float]], ta: list[list[float]], e: float, skin: float, n: int,
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
    return _Point(x, a[0], a[1], sign_changes(a, n), sign_changes(s, n), pt, qt, tols)


def clearly_positive(pt: _Point, n: int, w: float, direction: int) -> bool:
    """The C runtime's first-order exclusion test, then its second-order one, at a Point."""
    return bounds_positive(pt.qt, pt.tol, n, w, direction)


def bounds_positive(qt: Sequence[float], tol: Sequence[float], n: int, w: float,
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
    h = div(-L1, 2 * L2)
    h = 0.0 if h < 0 else (w if h > w else h)
    m = L0 + h * (L1 + h * L2)
    size = abs(L0) + h * (abs(L1) + h * L2)
    return m > 2 * rel * size


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


def bernstein_test(pt: _Point, n: int, w: float, keep: bool) -> _Bernstein:
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
    one = certain and sign_changes(ap, n) == 1
    return _Bernstein(BERN_ONE if one else BERN_UNKNOWN, ap[n], q)


def _bernstein_signs(b: Sequence[float], tol: float) -> tuple[bool, int, bool]:
    """(every |b_j| > tol, sign changes, every b_j > 0) -- zeros not skipped (unlike
    sign_changes: a certain coefficient is never 0)."""
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
# end (C DIP_INSIDE: bernstein_clear, isolate_first_root)
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


def bernstein_clear(q: _BernQ, n: int, t0: float) -> bool:
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


def derivative(p: Sequence[float], n: int) -> list[float]:
    """The coefficients of p' (p of degree n)."""
    return [(i + 1) * p[i + 1] for i in range(n)]
