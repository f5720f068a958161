"""reckon.deadline: the first time a held segment drifts past the tolerance, against sampling."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from max2code.server.reckon import (SMOOTH, SOON, _at, _first_exceed, chord, deadline, fitted, hop_bound,
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
    faster = (2.0, *_at(held, 2.0)[:3], 1.001, 0, 0, 0, 0)
    assert deadline(held, faster, 2.0, 0.0, 1.0) == 2.0                      # exact: at once
    assert deadline(held, faster, 2.0, 0.01, 1.0) == pytest.approx(2.0 + 0.005 / 0.001)  # 5 s of drift
    visible = (2.0, *_at(held, 2.0)[:3], 2.0, 0, 0, 0, 0)
    assert deadline(held, visible, 2.0, 0.01, 1.0) == 2.0                    # within SOON
    spin = (2.0, *_at(held, 2.0)[:3], 1.0, 0, 1e-3, 0, 0)
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
        a, b = _at(truth, t + s), _at(m, t + s)
        assert a[:3] == pytest.approx(b[:3], abs=1e-15)
    mid = _at(truth, t + h / 2)[1] - _at(m, t + h / 2)[1]
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


@settings(max_examples=200, deadline=None)
@given(st.floats(-1, 1), st.floats(-20, 20), st.floats(0.05, 1), st.floats(1e-5, 1e-3))
def test_deadline_of_a_held_quadratic_against_sampling(w, alpha, reach, eps):
    """A quadratic's angle (angle + omega s + alpha s^2/2, protocol version 5) against a truth
    turning at a constant spin from the same pose: the drift at the reach first reaches eps/2 at
    the deadline, in closed form the least s > 0 with reach |dw s + alpha s^2/2| = eps/2 (dw
    the truth's spin less the quadratic's). A sign error in alpha moves it."""
    held = (0.9, 0.0, 0.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, alpha)    # (held since 0.9: at 1.0 it
    truth = (1.0, 0.0, 0.0, 0.3 + alpha * 0.01 / 2, 0.0, 0.0, w + alpha * 0.1, 0.0, 0.0)  # is here)
    d = deadline(held, truth, 1.0, eps, reach, soon=0.0) - 1.0
    e = eps / 2 / reach
    roots = [s for level in (e, -e) for s in _roots(-alpha / 2, w, -level) if s > 0]
    assert d == pytest.approx(min(roots, default=math.inf), rel=1e-9)


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
