"""reckon.deadline: the first time a held segment drifts past the tolerance, against sampling."""

from __future__ import annotations

import math

import pytest
from hypothesis import assume, example, given, settings, strategies as st

from max2code.server.reckon import (SMOOTH, SOON, state_at, _first_exceed, chord, deadline, fitted, hop_bound,
                                    next_tick)

small = st.floats(-3, 3, allow_nan=False)


@settings(max_examples=300, deadline=None)
@given(small, small, small, st.floats(0.01, 1))
def test_first_exceed_against_sampling(c, b, a, e):
    s = _first_exceed(c, b, a, e)
    f = lambda t: abs(c + b * t + a * t * t / 2)  # noqa: E731
    if abs(c) > e:
        assert s == 0
        return
    # below e everywhere before s (sampled), and at e at s
    horizon = min(s, 50.0)
    for k in range(200):
        assert f(horizon * k / 200) <= e * (1 + 1e-9) + 1e-12
    if math.isfinite(s):
        assert abs(f(s) - e) <= 1e-9 * max(1.0, abs(c) + abs(b) * s + abs(a) * s * s)


def test_deadline_rules():
    held = (0.0, 0, 0, 0, 1.0, 0, 0, 0, 0)
    assert deadline(held, held, 2.0, 0.01, 1.0) == math.inf                 # the same motion
    faster = (2.0, *state_at(held, 2.0)[:3], 1.001, 0, 0, 0, 0)
    assert deadline(held, faster, 2.0, 0.0, 1.0) == 2.0                      # exact: at once
    assert deadline(held, faster, 2.0, 0.01, 1.0) == pytest.approx(2.0 + 0.005 / 0.001)  # 5 s of drift
    visible = (2.0, *state_at(held, 2.0)[:3], 2.0, 0, 0, 0, 0)
    assert deadline(held, visible, 2.0, 0.01, 1.0) == 2.0                    # within SOON
    spin = (2.0, *state_at(held, 2.0)[:3], 1.0, 0, 1e-3, 0, 0)
    assert deadline(held, spin, 2.0, 0.01, 2.0) > 2.0 + SOON                  # slow turn: waits


def test_chord_meets_the_flight_at_both_ticks_and_hops_at_most_a_h2_over_8():
    """A held body's flight between ticks (c + v s + a s^2/2) against the chord clients get:
    equal at t and at the next tick T, apart by |a| (T - t)^2 / 8 at the midpoint (the closed
    form of a parabola's sagitta), and the ticks found from times a few ulps off k h."""
    h = 1 / 240
    truth = (0.5, 1.0, 2.0, 0.3, 0.1, 9.81 * h / 2, -2.0, 0.0, -9.81)   # a hop, turning
    t = 121 * h
    assert next_tick(t, h) == 122 * h and next_tick(t * (1 + 4e-16), h) == 122 * h
    assert next_tick(121.5 * h, h) == 122 * h
    m = chord(truth, t, h)
    assert m[0] == t and m[7:] == (0.0, 0.0) and m[6] == truth[6]
    for s in (0.0, h):
        a, b = state_at(truth, t + s), state_at(m, t + s)
        assert a[:3] == pytest.approx(b[:3], abs=1e-15)
    mid = state_at(truth, t + h / 2)[1] - state_at(m, t + h / 2)[1]
    assert mid == pytest.approx(9.81 * h * h / 8, rel=1e-9)   # (above it: a hop)
    assert hop_bound(truth, h, 1e-5) == pytest.approx(1e-5 + 9.81 * h * h / 8)


def test_deadline_counts_angles_a_turn_apart_as_equal():
    held = (0.0, 0, 0, math.pi - 1e-3, 0, 0, 0, 0, 0)
    wrapped = (0.0, 0, 0, -math.pi - 1e-3 + 2e-9, 0, 0, 0, 0, 0)   # the engine wrapped it
    assert deadline(held, wrapped, 0.0, 1e-6, 1.0) == math.inf


def test_first_exceed_on_the_edge_going_out_by_a_subnormal_rate():
    """|c| = e and a rate of the least subnormal outwards: beyond at once (0). c * b underflowed
    to 0 and the edge was taken as not going out: inf, never (hypothesis found c = 0.5,
    b = 5e-324, a = 1, e = 0.5)."""
    assert _first_exceed(0.5, 5e-324, 1.0, 0.5) == 0.0
    assert _first_exceed(-0.5, -5e-324, -1.0, 0.5) == 0.0
    assert _first_exceed(0.5, 0.0, 5e-324, 0.5) == 0.0
    assert _first_exceed(0.5, -5e-324, 1.0, 0.5) > 0.0      # (inwards first)


def test_first_exceed_back_at_the_edge_after_a_subnormal_rate_inwards():
    """|c| = e, a rate of the least subnormal inwards and an acceleration outwards: back at the
    edge at -2 b / a = 5e-324 and beyond after. The formula's discriminant b^2 underflowed to 0,
    its roots to 0, and the first exceed was taken at the other edge, a second later
    (hypothesis found c = e = 1, b = -5e-324, a = 2)."""
    assert _first_exceed(1.0, -5e-324, 2.0, 1.0) == 5e-324
    assert _first_exceed(-1.0, 5e-324, -2.0, 1.0) == 5e-324


def test_first_exceed_of_subnormal_rate_and_acceleration():
    """A subnormal acceleration (-5e-322, what deadline() made of a held quadratic's alpha =
    1e-320 at a reach of 0.05; its spin difference underflowed to 0): the drift a s^2/2 reaches
    e = 5e-6 only after 1.4e158 s. The discriminant's product underflowed to 0 and the root
    came out as qc / 0, never (the formula now works on the coefficients scaled by a power of
    two). Against mpmath's roots of the same doubles, to the polish's rounding."""
    for b, a, e in ((0.0, -5e-322, 5e-6), (0.0, 1e-320, 1e-4), (5e-324, 1e-320, 1e-4),
                    (-5e-324, 1e-320, 1e-4), (1e-321, -3e-318, 0.25)):
        want = min(s for level in (e, -e) for s in _roots(a, 2 * b, -2 * level) if s > 0)
        assert _first_exceed(0.0, b, a, e) == pytest.approx(want, rel=1e-12)


@settings(max_examples=200, deadline=None)
@given(st.floats(-1, 1, allow_subnormal=False), st.floats(-20, 20, allow_subnormal=False),
       st.floats(0.05, 1), st.floats(1e-5, 1e-3))
@example(9.06e-4, 9.06e-4, 1.0, 9.06e-4)   # the drift touches eps/2 at s = 1 and turns back
def test_deadline_of_a_held_quadratic_against_sampling(w, alpha, reach, eps):
    """A quadratic's angle (angle + omega s + alpha s^2/2, protocol version 5) against a truth
    turning at a constant spin from the same pose: the drift at the reach first reaches eps/2 at
    the deadline, in closed form the least s > 0 with reach |dw s + alpha s^2/2| = eps/2 (dw
    the truth's spin less the quadratic's). A sign error in alpha moves it. (Normal numbers
    only: with a subnormal alpha the truth's spin w + 0.1 alpha is rounded to a few digits, so
    the drift the deadline sees is not the one this closed form is given; subnormal
    coefficients are checked on _first_exceed's own inputs above.)

    Where the drift only touches eps/2 and turns back (w^2 = 2 alpha eps/2: the example), the
    rounding of the numbers decides whether it reaches it: the deadline may come at the touch
    or at the next crossing, never before the drift is within a billionth of eps/2 nor after it
    has passed it. (helper-53 drew that example: a closed form taken to the exact level gave the
    next crossing, 2.414, and the deadline the touch, 1.)"""
    held = (0.9, 0.0, 0.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, alpha)    # (held since 0.9: at 1.0 it
    truth = (1.0, 0.0, 0.0, 0.3 + alpha * 0.01 / 2, 0.0, 0.0, w + alpha * 0.1, 0.0, 0.0)  # is here)
    d = deadline(held, truth, 1.0, eps, reach, soon=0.0) - 1.0
    e = eps / 2 / reach

    def first(level: float) -> float:
        return min((s for lv in (level, -level) for s in _roots(-alpha / 2, w, -lv) if s > 0),
                   default=math.inf)
    earliest, latest = first(e * (1 - 1e-9)), first(e * (1 + 1e-9))
    if latest == earliest:   # (no root near: the same crossing at both levels, or none)
        assert d == pytest.approx(first(e), rel=1e-9)
    else:
        assert earliest * (1 - 1e-9) <= d <= latest * (1 + 1e-9)


def _roots(a: float, b: float, c: float) -> list[float]:
    """Real roots of a s^2 + b s + c: the textbook formula in mpmath at 700 digits (an
    independent oracle; enough that no cancellation matters even for a subnormal a)."""
    import mpmath

    with mpmath.workdps(700):
        a, b, c = mpmath.mpf(a), mpmath.mpf(b), mpmath.mpf(c)
        if a == 0:
            return [float(-c / b)] if b else []
        disc = b * b - 4 * a * c
        if disc < 0:
            return []
        return [float((-b - mpmath.sqrt(disc)) / (2 * a)), float((-b + mpmath.sqrt(disc)) / (2 * a))]


H = 1 / 240


def _history(p, t: float, k: int) -> list[tuple[float, float, float, float]]:
    return [(t - j * H, *p(t - j * H)) for j in range(k, 0, -1)]


def _truth(p, t: float, g: float = -9.81) -> tuple[float, ...]:
    """The free flight from p(t) under g that meets p at the next tick (as the solver's is)."""
    (x, y, a), (x1, y1, a1) = p(t), p(t + H)
    return (t, x, y, a, (x1 - x) / H, (y1 - y) / H - g * H / 2, (a1 - a) / H, 0.0, g)


def test_fitted_recovers_a_quadratic_history_and_refuses_jitter():
    """Tick poses on a closed-form quadratic (x, y and angle): the fit's velocities and
    accelerations are its derivatives at t, and its estimated life is long (no jerk); the same
    poses jittered by the bound at alternate ticks are not smooth (None); three poses are too
    few."""
    vx, vy, w, ax, ay, al = 0.4, -0.2, -1.5, 2.0, -1.0, -6.0
    p = lambda s: (0.1 + vx * s + ax * s * s / 2, 0.3 + vy * s + ay * s * s / 2,  # noqa: E731
                   0.5 + w * s + al * s * s / 2)
    t = 30 * H
    bound, reach = 3.1e-5, 0.35
    fit = fitted(_history(p, t, 5), _truth(p, t), t, H, bound, reach)
    m = fit.motion
    assert m[:4] == pytest.approx((t, *p(t)), abs=1e-12)
    v_t = (vx + ax * t, vy + ay * t, w + al * t)
    assert m[4:7] == pytest.approx(v_t, abs=1e-6)
    assert m[7:] == pytest.approx((ax, ay, al), rel=1e-3)
    assert fit.life > 0.1 and fit.chord_life < 0.01    # the chord drifts as |a| s^2 / 2
    jitter = [(tk, x + bound * (-1) ** k, y, a) for k, (tk, x, y, a) in enumerate(_history(p, t, 5))]
    assert fitted(jitter, _truth(p, t), t, H, bound, reach) is None
    assert fitted(_history(p, t, 2), _truth(p, t), t, H, bound, reach) is None
    assert SMOOTH < 1


def test_fitted_life_is_the_cubic_closed_form():
    """A history on a cubic angle (jerk j, nothing else moving): the quadratic's estimated life
    is (6 bound / (|j| reach))^(1/3), where the cubic's term alone reaches the bound."""
    j, reach, bound = 40.0, 0.35, 3.1e-5
    p = lambda s: (0.0, 0.0, 0.2 + 0.5 * s + 2 * s * s + j * s ** 3 / 6)  # noqa: E731
    t = 0.5
    fit = fitted(_history(p, t, 6), _truth(p, t, 0.0), t, H, bound, reach)
    assert fit is not None
    assert fit.life == pytest.approx((6 * bound / (j * reach)) ** (1 / 3), rel=0.05)


def _cubic_roots(j: float, a: float, b: float, c: float) -> list[float]:
    """Real roots of j s^3/6 + a s^2/2 + b s + c, by mpmath at 60 digits (an independent
    oracle: its polynomial root finder, not bisection)."""
    import mpmath

    with mpmath.workdps(60):
        coeffs = [mpmath.mpf(j) / 6, mpmath.mpf(a) / 2, mpmath.mpf(b), mpmath.mpf(c)]
        try:
            roots = mpmath.polyroots(coeffs[::-1], maxsteps=400, extraprec=400, asc=True)
        except mpmath.libmp.libhyper.NoConvergence:     # (a double root, a tangent)
            assume(False)
        return [float(mpmath.re(r)) for r in roots if abs(mpmath.im(r)) < mpmath.mpf(10) ** -30]


@settings(max_examples=200, deadline=None)
@given(st.floats(-0.99, 0.99), st.floats(-3, 3), st.floats(-3, 3),
       st.floats(0.05, 30).flatmap(lambda m: st.sampled_from([m, -m])), st.floats(0.01, 1))
def test_first_exceed_with_a_jerk_against_mpmath(c, b, a, j, e):
    """A held cubic's drift c + b s + a s^2/2 + j s^3/6 (protocol version 6) first leaves
    [-e, e] at the least positive root of the cubic less or plus e where it crosses: against
    mpmath's roots of both. (A jerk is never 0 here; a sign or a factor in its term moves it.)"""
    c *= e      # (inside: the edges are test_first_exceed_on_the_edge_...'s)
    s = _first_exceed(c, b, a, e, j)
    f = lambda t: c + b * t + a * t * t / 2 + j * t ** 3 / 6  # noqa: E731
    slope = lambda t: b + a * t + j * t * t / 2  # noqa: E731
    crossings = [r for level in (e, -e) for r in _cubic_roots(j, a, b, c - level) if r > 0
                 and abs(slope(r)) > 1e-6]                  # (a tangent touches, never leaves)
    first = min(crossings)                                  # (a cubic always leaves)
    assume(all(abs(r - first) > 1e-6 for r in _cubic_roots(j, a, b, c - e) + _cubic_roots(j, a, b, c + e)
               if r > 0 and abs(slope(r)) <= 1e-6))
    assert s == pytest.approx(first, rel=1e-9, abs=1e-12)
    assert s <= first * (1 + 1e-12)                        # (never late, to rounding)
    assert all(abs(f(s * k / 100)) <= e * (1 + 1e-12) for k in range(101))


def test_deadline_of_a_held_cubic_against_mpmath():
    """A cubic's angle (angle + omega s + alpha s^2/2 + ja s^3/6) held from 0.9, against a
    truth at a constant spin from its pose at 1.0: the drift at the reach reaches eps/2 at the
    least root of reach (dw s - alpha' s^2/2 - ja s^3/6) = -+eps/2, with alpha' and dw those of
    the cubic re-expressed at 1.0. With the jerk's sign flipped the deadline moves."""
    ja, al, reach, eps = 30.0, -2.0, 0.35, 6.2e-5
    held = (0.9, 0.0, 0.0, 0.3, 0.0, 0.0, 0.5, 0.0, 0.0, al, 0.0, 0.0, ja)
    at = state_at(held, 1.0)
    assert at[2] == pytest.approx(0.3 + 0.05 + al * 0.01 / 2 + ja * 0.001 / 6, rel=1e-12)
    assert at[5] == pytest.approx(0.5 + al * 0.1 + ja * 0.01 / 2, rel=1e-12)
    truth = (1.0, 0.0, 0.0, at[2], 0.0, 0.0, 0.6, 0.0, 0.0)
    d = deadline(held, truth, 1.0, eps, reach, soon=0.0) - 1.0
    dw, a2 = 0.6 - at[5], al + ja * 0.1
    roots = [s for level in (eps / 2, -eps / 2)
             for s in _cubic_roots(-reach * ja, -reach * a2, reach * dw, -level) if s > 0]
    assert d == pytest.approx(min(roots), rel=1e-9)
    flipped = held[:12] + (-ja,)
    assert deadline(flipped, truth, 1.0, eps, reach, soon=0.0) - 1.0 != pytest.approx(d, rel=1e-3)


def test_fitted_cubic_recovers_a_cubic_history():
    """Tick poses on a closed-form cubic (x, y and angle): the cubic's velocities,
    accelerations and jerks are its derivatives at t (to the digits the fit keeps), and its
    estimated life is long (no snap); on a quartic angle (snap q) its life is
    (24 bound / (|q| reach))^(1/4), where the quartic's term alone reaches the bound."""
    vx, vy, w, ax, ay, al, jx, jy, ja = 0.4, -0.2, -1.5, 2.0, -1.0, -6.0, 3.0, -5.0, 40.0
    p = lambda s: (0.1 + vx * s + ax * s * s / 2 + jx * s ** 3 / 6,  # noqa: E731
                   0.3 + vy * s + ay * s * s / 2 + jy * s ** 3 / 6,
                   0.5 + w * s + al * s * s / 2 + ja * s ** 3 / 6)
    t = 30 * H
    bound, reach = 3.1e-5, 0.35
    fit = fitted(_history(p, t, 6), _truth(p, t), t, H, bound, reach)
    m = fit.cubic
    assert m[:4] == pytest.approx((t, *p(t)), abs=1e-12)
    assert m[4:7] == pytest.approx((vx + ax * t + jx * t * t / 2, vy + ay * t + jy * t * t / 2,
                                    w + al * t + ja * t * t / 2), abs=1e-6)
    assert m[7:10] == pytest.approx((ax + jx * t, ay + jy * t, al + ja * t), rel=1e-3)
    assert m[10:] == pytest.approx((jx, jy, ja), rel=2e-2)
    assert fit.cubic_life > 0.1
    q = 300.0
    quartic = lambda s: (0.0, 0.0, 0.2 + 0.5 * (s - 0.5) + 2 * (s - 0.5) ** 2  # noqa: E731
                         + q * (s - 0.5) ** 4 / 24)     # (no jerk at 0.5: its snap alone)
    fit = fitted(_history(quartic, 0.5, 6), _truth(quartic, 0.5, 0.0), 0.5, H, bound, reach)
    assert fit.cubic is not None
    assert fit.cubic_life == pytest.approx((24 * bound / (q * reach)) ** (1 / 4), rel=0.1)
