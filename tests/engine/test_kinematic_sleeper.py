"""A kinematic body never passes through a sleeping one (issue 33, item 2).

An asleep body predicts nothing and a kinematic one never predicts, so a paddle swept through a
ball at rest with no event at all (overlap 0.18 m, the ball asleep throughout). The sleeper now
watches the kinematic bodies: it wakes when one reaches it and takes the impulse."""

from __future__ import annotations

import pytest

from .scenes import assert_apart


@pytest.mark.parametrize("speed", [1.0, 7.0])
def test_kinematic_paddle_sweeps_a_ball_at_rest(engine, speed):
    w = engine.World(gravity=(0, -9.81))
    w.add_segment((-30, 0), (60, 0))
    ball = w.add_circle((0, 0.5), 0.1, restitution=0.5)
    paddle = w.add_polygon([(-0.1, 0), (0.1, 0), (0.1, 0.3), (-0.1, 0.3)], kind="kinematic",
                           position=(-0.2 - 2.5 * speed, 0.02), velocity=(speed, 0), restitution=1.0)
    w.step_to(2.0)
    assert w.asleep(ball)
    events = w.step_to(3.0)
    assert ("wake", ball) in [(e.kind, e.a) for e in events]
    hit = [e for e in events if e.kind == "collision" and {e.a, e.b} == {ball, paddle}]
    assert hit and hit[0].time == pytest.approx(2.5, abs=1e-9)
    assert_apart(w)
    # e = 0.5 off a body of infinite mass: the ball leaves at 1.5 times the paddle's speed
    assert w.velocity(ball)[0] == pytest.approx(1.5 * speed, rel=1e-9)
    assert w.pose(ball)[0] > w.pose(paddle)[0] + 0.2 - 1e-9
