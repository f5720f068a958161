"""Dead reckoning with a drawn tolerance: when a client's segment of a body stops being good
enough. IEEE 1278 (DIS) re-sends an entity's state when the receivers' motion model drifts
from the truth beyond a threshold; here both the model and the truth are exact segments
(c + v s + a s^2/2, angle + omega s), so the time the drift reaches the threshold is the first
root of a quadratic per axis, and the threshold may be 0 (every change is sent: exact).

With tolerance eps, a body's new segment is not sent while the one clients hold stays within
eps/2 per axis (so within eps / sqrt(2) of the truth, rotation included at the body's bounding
radius), and is sent at the latest when it would leave that: the server wakes then. A change
that becomes visible within SOON is sent at once, at its event's exact time, with its event.
"""

from __future__ import annotations

import math

Motion = tuple[float, ...]   # (t0, x, y, angle, vx, vy, omega, ax, ay)


def _at(m: Motion, t: float) -> tuple[float, ...]:
    t0, x, y, th, vx, vy, w, ax, ay = m
    s = t - t0
    return (x + s * (vx + 0.5 * ax * s), y + s * (vy + 0.5 * ay * s), th + w * s,
            vx + ax * s, vy + ay * s, w, ax, ay)


def _first_exceed(c: float, b: float, a: float, e: float) -> float:
    """The least s >= 0 with |c + b s + a s^2/2| > e (inf if never, 0 if already)."""
    out = (lambda v: v > 0) if c > 0 else (lambda v: v < 0)   # (signs, not products: a
    if abs(c) > e or (abs(c) == e and (out(b) or (b == 0 and out(a)))):  # product underflows)
        return 0.0      # beyond already, or on the edge and going out
    best = math.inf
    for level in (e, -e):
        # a s^2 + 2 b s + 2 (c - level) = 0 (doubled rather than a/2: half the least
        # subnormal a is 0, which would take the linear root of a quadratic)
        qa, qb, qc = a, 2.0 * b, 2.0 * (c - level)
        if qa == 0:
            if qb != 0:
                s = -qc / qb
                if s > 0:
                    best = min(best, s)
            continue
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


SOON = 0.05   # seconds: a change visible within this is sent at once, with its event


def deadline(held: Motion, truth: Motion, now: float, eps: float, reach: float,
             soon: float = SOON) -> float:
    """When the held segment first drifts from the truth by more than eps/2 along x or y, or
    by more than eps/2 at `reach` from the reference point through rotation (both segments
    valid from `now`); `now` when eps is 0 or they already differ that much, or when that
    comes within `soon`."""
    if eps <= 0:
        return now
    h, g = _at(held, now), _at(truth, now)
    e = eps / 2
    turn = g[2] - h[2]      # (angles a whole turn apart draw the same: the engine wraps them)
    turn -= 2 * math.pi * round(turn / (2 * math.pi))
    s = min(_first_exceed(g[0] - h[0], g[3] - h[3], g[6] - h[6], e),
            _first_exceed(g[1] - h[1], g[4] - h[4], g[7] - h[7], e),
            _first_exceed(reach * turn, reach * (g[5] - h[5]), 0.0, e) if reach > 0 else math.inf)
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
    x, y, th, vx, vy, w, ax, ay = _at(truth, t)
    half = (next_tick(t, h) - t) / 2
    return (t, x, y, th, vx + ax * half, vy + ay * half, w, 0.0, 0.0)


def hop_bound(truth: Motion, h: float, slop: float) -> float:
    """How far (per axis, and through rotation at a body's reach) a client's chord of a held
    body may be from the truth: the hop, |a| h^2 / 8 (the flight between two ticks is that far
    from its chord at most), plus the solver's slop (a held pair may overlap that much: the
    solver itself places such a body only to within it)."""
    return slop + math.hypot(truth[7], truth[8]) * h * h / 8
