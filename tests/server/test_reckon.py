"""reckon.deadline: the first time a held segment drifts past the tolerance, against sampling."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from max2code.server.reckon import SOON, _at, _first_exceed, chord, deadline, hop_bound, next_tick

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
