"""reckon.deadline: the first time a held segment drifts past the tolerance, against sampling."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from max2code.server.reckon import SOON, _at, _first_exceed, deadline

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
