"""Dead reckoning with a drawn tolerance: when a client's segment of a body stops being good
enough. IEEE 1278 (DIS) re-sends an entity's state when the receivers' motion model drifts
from the truth beyond a threshold; here both the model and the truth are exact segments
(c + v s + a s^2/2, angle + omega s, and for a held body's quadratic + alpha s^2/2, its cubic
+ j s^3/6), so the time the drift reaches the threshold is the first root of a quadratic (a
cubic's) per axis, and the threshold may be 0 (every change is sent: exact).

With tolerance eps, a body's new segment is not sent while the one clients hold stays within
eps/2 per axis (so within eps / sqrt(2) of the truth, rotation included at the body's bounding
radius), and is sent at the latest when it would leave that: the server wakes then. A change
that becomes visible within SOON is sent at once, at its event's exact time, with its event.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

Motion = tuple[float, ...]   # (t0, x, y, angle, vx, vy, omega, ax, ay[, alpha[, jx, jy, ja]])


def state_at(m: Motion, t: float) -> tuple[float, ...]:
    """(x, y, angle, vx, vy, omega, ax, ay, alpha, jx, jy, ja) at t; alpha (the angular
    acceleration of a held body's quadratic, `fitted`) and the jerks (jx, jy and ja, the
    angle's: a held body's cubic, protocol version 6) are 0 in the core's motions, which have
    none. (wire.at evaluates a held body's fit with this too.)"""
    t0, x, y, th, vx, vy, w, ax, ay = m[:9]
    al = m[9] if len(m) > 9 else 0.0
    jx, jy, ja = (tuple(m[10:13]) + (0.0, 0.0, 0.0))[:3]
    s = t - t0
    if jx or jy or ja:
        return (x + s * (vx + s * (0.5 * ax + jx * s / 6)), y + s * (vy + s * (0.5 * ay + jy * s / 6)),
                th + s * (w + s * (0.5 * al + ja * s / 6)), vx + s * (ax + 0.5 * jx * s),
                vy + s * (ay + 0.5 * jy * s), w + s * (al + 0.5 * ja * s),
                ax + jx * s, ay + jy * s, al + ja * s, jx, jy, ja)
    return (x + s * (vx + 0.5 * ax * s), y + s * (vy + 0.5 * ay * s), th + s * (w + 0.5 * al * s),
            vx + ax * s, vy + ay * s, w + al * s, ax, ay, al, 0.0, 0.0, 0.0)


def _first_exceed(c: float, b: float, a: float, e: float, j: float = 0.0) -> float:
    """The least s >= 0 with |c + b s + a s^2/2 + j s^3/6| > e (inf if never, 0 if already);
    with a jerk j, at most that (`_first_exceed_cubic`)."""
    out = (lambda v: v > 0) if c > 0 else (lambda v: v < 0)   # (signs, not products: a
    if abs(c) > e or (abs(c) == e and (out(b) or (b == 0 and (out(a) or (a == 0 and out(j)))))):
        return 0.0      # beyond already, or on the edge and going out (a product underflows)
    if j:
        return _first_exceed_cubic(c, b, a, j, e)
    best = math.inf
    for level in (e, -e):
        # a s^2 + 2 b s + 2 (c - level) = 0 (doubled rather than a/2: half the least
        # subnormal a is 0, which would take the linear root of a quadratic)
        qa, qb, qc = a, 2.0 * b, 2.0 * (c - level)
        if qc == 0 and qa != 0:     # on this edge: back at it at -2 b / a (the formula's
            s = -2.0 * b / a        # discriminant b^2 underflows for a subnormal b)
            if s > 0:
                best = min(best, s)
            continue
        if qa == 0:
            if qb != 0:
                s = -qc / qb
                if s > 0:
                    best = min(best, s)
            continue
        # scaled by a power of two (exact) so the largest is about 1: with a subnormal a and
        # b both products underflowed to 0, the discriminant with them, and the root came out
        # as qc / 0 = never where it was 1.4e158 s (a = 1e-320, b = 5e-324, e = 1e-4)
        k = math.frexp(max(abs(qa), abs(qb), abs(qc)))[1]
        qa, qb, qc = math.ldexp(qa, -k), math.ldexp(qb, -k), math.ldexp(qc, -k)
        disc = qb * qb - 4 * qa * qc
        if disc < 0:
            continue
        r = math.sqrt(disc)
        q = -0.5 * (qb + math.copysign(r, qb))     # the stable form of the two roots
        for s in ((q / qa) if qa else math.inf, (qc / q) if q else math.inf):
            if s > 0:
                best = min(best, _polish(c - level, b, a, s))
    return best


def _polish(c: float, b: float, a: float, s: float) -> float:
    """Newton steps on c + b s + a s^2/2 = 0 from a root s of the formula: when the products
    of the discriminant fall into subnormal numbers (a tiny acceleration over a long time) the
    formula's root is off by percents; a few steps make it exact to rounding. ((a s) s, not
    a s^2: s^2 alone may overflow.)"""
    for _ in range(60):
        slope = b + a * s
        if not math.isfinite(s) or slope == 0:
            break
        step = (c + b * s + (a * s) * s / 2) / slope
        if not math.isfinite(step) or abs(step) <= 1e-15 * abs(s) or s - step <= 0:
            break
        s -= step
    return s


def _first_exceed_cubic(c: float, b: float, a: float, j: float, e: float) -> float:
    """_first_exceed with a jerk j != 0, |c| <= e: f(s) = c + b s + a s^2/2 + j s^3/6 is
    monotonic between the roots of f' (b + a s + j s^2/2), so on each such piece from 0 on
    |f| passes e at most once per level; the first piece where it does is bisected to the
    last s known inside (never after the true crossing: a deadline early by rounding only
    re-sends sooner)."""
    f = lambda s: c + s * (b + s * (0.5 * a + j * s / 6))     # noqa: E731
    qa, qb, qc = 0.5 * j, a, b
    disc = qb * qb - 4 * qa * qc
    ends = []
    if disc > 0:
        r = math.sqrt(disc)
        q = -0.5 * (qb + math.copysign(r, qb))
        ends = sorted(s for s in ((q / qa), (qc / q) if q else math.inf) if 0 < s < math.inf)
    lo = 0.0
    for hi in ends + [math.inf]:
        if hi == math.inf:      # the last piece: f goes to the sign of j's infinity
            hi = max(2 * lo, 1e-9)
            while abs(f(hi)) <= e:
                if hi > 1e300:
                    return math.inf
                lo, hi = hi, 2 * hi
        if abs(f(hi)) > e:
            for _ in range(200):    # (lo inside, hi outside)
                mid = 0.5 * (lo + hi)
                if mid <= lo or mid >= hi:
                    break
                if abs(f(mid)) > e:
                    hi = mid
                else:
                    lo = mid
            return lo
        lo = hi
    return math.inf


SOON = 0.05   # seconds: a change visible within this is sent at once, with its event


def deadline(held: Motion, truth: Motion, now: float, eps: float, reach: float,
             soon: float = SOON) -> float:
    """When the held segment first drifts from the truth by more than eps/2 along x or y, or
    by more than eps/2 at `reach` from the reference point through rotation (both segments
    valid from `now`); `now` when eps is 0 or they already differ that much, or when that
    comes within `soon`."""
    if eps <= 0:
        return now
    h, g = state_at(held, now), state_at(truth, now)
    e = eps / 2
    turn = g[2] - h[2]      # (angles a whole turn apart draw the same: the engine wraps them)
    turn -= 2 * math.pi * round(turn / (2 * math.pi))
    s = min(_first_exceed(g[0] - h[0], g[3] - h[3], g[6] - h[6], e, g[9] - h[9]),
            _first_exceed(g[1] - h[1], g[4] - h[4], g[7] - h[7], e, g[10] - h[10]),
            _first_exceed(reach * turn, reach * (g[5] - h[5]), reach * (g[8] - h[8]), e,
                          reach * (g[11] - h[11]))
            if reach > 0 else math.inf)
    return now if s < soon or s == 0 else now + s


def next_tick(t: float, h: float) -> float:
    """The contact solver's first tick after t. Its ticks are at the multiples of h, each the
    last plus h (so a few ulps off k h after many): a t within 1e-6 h of one is that tick."""
    k = round(t / h)
    if abs(t - k * h) <= 1e-6 * h:
        return (k + 1) * h
    return math.ceil(t / h) * h


def chord(truth: Motion, t: float, h: float) -> Motion:
    """What clients are sent for a body the contact solver holds, from time t: its pose at t,
    moving straight until the solver's next tick T at the mean velocity its free flight has
    over [t, T], no acceleration. Why: between ticks such a body flies freely under gravity
    and each tick pushes it back (docs/engine-contact.md), so its exact segment changes 240
    times a second even at rest; the chord is where it is at the ticks (semi-implicit Euler's
    positions), at most |a| (T - t)^2 / 8 from its flight in between (the hop), and a body at
    rest or rolling steadily keeps the same chord from tick to tick, so that clients need no
    new one (room.py: re-sent only when the truth leaves `hop_bound`)."""
    x, y, th, vx, vy, w, ax, ay = state_at(truth, t)[:8]
    half = (next_tick(t, h) - t) / 2
    return (t, x, y, th, vx + ax * half, vy + ay * half, w, 0.0, 0.0)


def hop_bound(truth: Motion, h: float, slop: float) -> float:
    """How far (per axis, and through rotation at a body's reach) a client's chord of a held
    body may be from the truth: the hop, |a| h^2 / 8 (the flight between two ticks is that far
    from its chord at most), plus the solver's slop (a held pair may overlap that much: the
    solver itself places such a body only to within it)."""
    return slop + math.hypot(truth[7], truth[8]) * h * h / 8



HISTORY = 6     # a held body's past tick poses its quadratic is fitted to (`fitted`)
CUBIC_HISTORY = 4   # and its cubic: the jerk changes within HISTORY ticks of a tipping box
SMOOTH = 0.25   # of the bound: the fit's largest residual for that history to count as smooth
# a quadratic is sent only when its bytes a second, by the estimated lives, are below this
# fraction of the chord's: the estimate is optimistic (tipping-box's quadratics lasted 4.5 ticks,
# median, where 6.7 were estimated; 8.5 where 12 at a quarter pixel)
CHEAPER = 0.8
# the same for a cubic, against the cheaper of the two: a pile's jittery cubics cost 4 % of its
# quarter-pixel bytes at 0.8; at 0.65 tipping-box and compound lose nothing (and at 0.5 they
# lose most of their gain: `bench/serve.py --bytes`, docs/server.md)
CUBIC_CHEAPER = 0.65


def _taylor(d: list[tuple[float, float]], degree: int) -> tuple[list[float], float]:
    """The least-squares c_1 s + c_2 s^2/2 + ... + c_n s^n/n! (degree n) through the points
    (s, d) (a curve through (0, 0)), and its largest residual: the derivatives at 0 of the
    polynomial nearest a held body's recent poses, relative to its pose now. (Solved in
    u = s / max|s|: in s itself the normal equations of degree 4 over a few ticks span 15
    orders of magnitude.)"""
    span = max((abs(s) for s, _ in d), default=0.0) or 1.0
    basis = [lambda u, k=k: u ** k / math.factorial(k) for k in range(1, degree + 1)]
    n = len(basis)
    sol = solve([[sum(f(s / span) * g(s / span) for s, _ in d) for g in basis]
                 + [sum(f(s / span) * v for s, v in d)] for f in basis])
    if sol is None:
        return [0.0] * n, math.inf
    coef = [row[0] for row in sol]
    miss = max(abs(sum(c * f(s / span) for c, f in zip(coef, basis)) - v) for s, v in d)
    return [c / span ** (k + 1) for k, c in enumerate(coef)], miss


def solve(m: list[list[float]]) -> list[list[float]] | None:
    """Gauss-Jordan with partial pivoting on an augmented n x (n + k) system (normal
    equations, n <= 4): the solution for each of its k right-hand sides, as n rows of k;
    None when singular."""
    n = len(m)
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        if m[p][c] == 0:
            return None
        m[c], m[p] = m[p], m[c]
        for r in range(n):
            if r != c:
                f = m[r][c] / m[c][c]
                m[r] = [a - f * b for a, b in zip(m[r], m[c])]
    return [[v / m[k][k] for v in m[k][n:]] for k in range(n)]


@dataclass(frozen=True)
class Fit:
    """A held body's quadratic (`fitted`), its cubic (None when its own history is not
    smooth), and how long each and the chord would stay within the bound if the body went on
    as its recent poses do: the chord drifts from them as |a| s^2 / 2, the quadratic as
    |jerk| s^3 / 6, the cubic as |snap| s^4 / 24 (a, jerk and snap of the polynomials of
    degree 2, 3 and 4 nearest them)."""
    motion: Motion
    life: float          # seconds the quadratic lasts, estimated
    chord_life: float    # seconds the chord lasts, estimated
    cubic: Motion | None = None
    cubic_life: float = 0.0   # seconds the cubic lasts, estimated


def fitted(poses: list[tuple[float, float, float, float]], truth: Motion, t: float, h: float,
           bound: float, reach: float) -> Fit | None:
    """Second-order dead reckoning for a body the contact solver holds, from its own history:
    the quadratic (position and angle: c + v s + a s^2/2, angle + omega s + alpha s^2/2) from
    its pose at t, least-squares fitted to its last tick poses `poses` ((time, x, y, angle),
    oldest first) and its pose at the solver's next tick (its free flight gets there); None
    when fewer than four such poses, or when the history is not smooth: the fit misses one of
    them by more than SMOOTH x bound (along x or y, or through rotation at `reach`). Why only
    then: a box tipping over its corner turns with a growing spin and its centre moves on a
    circle, which the quadratic follows for several ticks where the chord fails within one;
    the solve's tick-to-tick jitter (a pile's) would make a quadratic drift, and the chord,
    which extrapolates nothing, is better there."""
    now = state_at(truth, t)
    tick = next_tick(t, h)
    samples = [(tk - t, x, y, th) for tk, x, y, th in poses if tk < t]
    samples.append((tick - t, *state_at(truth, tick)[:3]))
    if len(samples) < 4:
        return None
    recent = samples[-CUBIC_HISTORY - 1:]
    rates, life, chord_life = [], math.inf, math.inf
    cubic, cubic_life = [], math.inf
    for k in range(3):      # x, y, angle, each relative to its value now
        d = [(s, p[k] - now[k]) for s, *p in samples]
        if k == 2:          # (angles a whole turn apart draw the same: the engine wraps them)
            d = [(s, dv - 2 * math.pi * round(dv / (2 * math.pi))) for s, dv in d]
        scale = reach if k == 2 else 1.0
        (v, a), miss = _taylor(d, 2)
        if miss * scale > SMOOTH * bound:
            return None
        jerk = _taylor(d, 3)[0][2]
        rates.append((v, a))
        if a:
            chord_life = min(chord_life, math.sqrt(2 * bound / (abs(a) * scale)))
        if jerk:
            life = min(life, (6 * (bound - miss * scale) / (abs(jerk) * scale)) ** (1 / 3))
        # the cubic, from the last CUBIC_HISTORY ticks only (a tipping box's jerk changes
        # within HISTORY: over more ticks it extrapolates worse), where they are smooth
        if cubic is not None and len(recent) > 4:
            three, miss3 = _taylor(d[-len(recent):], 3)
            snap = _taylor(d, 4)[0][3] if len(d) > 4 else 0.0
            if miss3 * scale > SMOOTH * bound:
                cubic = None
            else:
                cubic.append(three)
                if snap:
                    cubic_life = min(cubic_life, (24 * (bound - miss3 * scale)
                                                  / (abs(snap) * scale)) ** (1 / 4))
        else:
            cubic = None
    # the accelerations (and jerks) with the fewest digits that move the quadratic (cubic) by
    # at most 1/16 of the bound over its estimated life (a fit's 10 digits are its noise;
    # clients hold the rounded numbers, and the room checks those against the truth at every
    # tick)
    scales = (1.0, 1.0, reach if reach > 0 else 1.0)
    span = min(life, 1.0)
    (vx, ax), (vy, ay), (w, al) = rates
    ax, ay, al = (_short(a, bound / (8 * span * span * r)) for a, r in zip((ax, ay, al), scales))
    quadratic = (t, now[0], now[1], now[2], vx, vy, w, ax, ay, al)
    if cubic is None:
        return Fit(quadratic, life, chord_life)
    span = min(cubic_life, 1.0)
    (cvx, cax, cjx), (cvy, cay, cjy), (cw, cal, cja) = cubic
    cax, cay, cal = (_short(a, bound / (8 * span * span * r)) for a, r in zip((cax, cay, cal), scales))
    cjx, cjy, cja = (_short(j, 3 * bound / (8 * span ** 3 * r)) for j, r in zip((cjx, cjy, cja), scales))
    return Fit(quadratic, life, chord_life,
               (t, now[0], now[1], now[2], cvx, cvy, cw, cax, cay, cal, cjx, cjy, cja), cubic_life)


def _short(v: float, within: float) -> float:
    """The number of fewest significant digits (at most 10) within `within` of v."""
    for digits in range(1, 10):
        r = float(f"{v:.{digits}g}")
        if abs(r - v) <= within:
            return r
    return v
