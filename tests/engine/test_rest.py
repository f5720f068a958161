"""The rest rule (engine/src/rest.c, README "The rest rule"): a ball bouncing with e < 1 comes
to rest at the analytic time and stays; a pile settles without overlap, without an exploding
event rate and without gaining energy; a ball on a slope slides as the analytic motion says."""

from __future__ import annotations

import math
import random

import pytest

from .scenes import assert_apart


@pytest.mark.parametrize("h,e", [(1.0, 0.5), (2.5, 0.8), (0.3, 0.2)])
def test_bouncing_ball_rests_at_the_analytic_time(engine, h: float, e: float) -> None:
    """Bounce times form a geometric series: first impact t1 = sqrt(2h/g) at speed v = sqrt(2gh),
    then flights of 2 v e^k / g: at rest at T = t1 + 2 v e / (g (1 - e))."""
    g, r = 9.81, 0.1
    w = engine.World(gravity=(0.0, -g))
    w.add_segment((-5.0, 0.0), (5.0, 0.0))
    ball = w.add_circle((0.0, h + r), r, restitution=e)
    events = w.step_to(10.0)
    rests = [ev for ev in events if ev.kind == "rest"]
    t1, v = math.sqrt(2 * h / g), math.sqrt(2 * g * h)
    T = t1 + 2 * v * e / (g * (1 - e))
    assert len(rests) == 1 and rests[0].a == ball
    assert abs(rests[0].time - T) <= 1e-12 * T
    bounces = [ev for ev in events if ev.kind == "collision"]
    # every bounce before the rest is where the series puts it
    for k, ev in enumerate(bounces[:5]):
        want = t1 + sum(2 * v * e ** j / g for j in range(1, k + 1))
        assert abs(ev.time - want) <= 1e-12 * want
    # and it stays: on the floor, asleep, for ever
    assert w.asleep(ball)
    for t in (10.0, 20.0, 100.0):
        w.step_to(t)
        x, y, _ = w.pose(ball)
        assert x == 0.0 and abs(y - r) <= 1e-9
    assert w.step_to(200.0) == []


def test_ball_slides_down_a_slope_after_resting(engine) -> None:
    """On a 10 degree slope a ball that stops bouncing slides: acceleration g sin(a) along it."""
    g, r, a = 9.81, 0.1, math.radians(10)
    w = engine.World(gravity=(0.0, -g))
    d = (math.cos(a), -math.sin(a))  # down the slope
    w.add_segment((-10 * d[0], -10 * d[1]), (10 * d[0], 10 * d[1]))
    n = (math.sin(a), math.cos(a))
    ball = w.add_circle((0.3 * n[0], 0.3 * n[1]), r, restitution=0.3)
    events = w.step_to(1.5)
    rest = [ev for ev in events if ev.kind == "rest"]
    assert rest and not w.asleep(ball)
    t0 = rest[0].time
    x0, y0, _ = w.pose(ball)
    vx0, vy0, _ = w.velocity(ball)
    s0 = vx0 * d[0] + vy0 * d[1]
    assert abs(vx0 * n[0] + vy0 * n[1]) <= 1e-12  # no normal motion any more
    for dt in (0.1, 0.5):
        x, y, _ = w.pose(ball, 1.5 + dt)
        along = s0 * dt + g * math.sin(a) * dt * dt / 2
        assert x == pytest.approx(x0 + along * d[0], abs=1e-12)
        assert y == pytest.approx(y0 + along * d[1], abs=1e-12)
    # the centre keeps its distance r from the slope
    for t in (1.5, 2.0):
        x, y, _ = w.pose(ball, t)
        assert abs(x * n[0] + y * n[1] - r) <= 1e-9
    assert t0 < 1.5


def _pile(engine, n: int = 40, seed: int = 2):
    rng = random.Random(seed)
    w = engine.World(gravity=(0.0, -9.81))
    W, H = 2.0, 4.0
    for a, b in [((0, 0), (W, 0)), ((W, 0), (W, H)), ((0, H), (0, 0))]:
        w.add_segment(a, b, restitution=0.8)
    pts: list[tuple[float, float]] = []
    while len(pts) < n:
        x, y = rng.uniform(0.15, W - 0.15), rng.uniform(0.5, H - 0.15)
        if all(math.hypot(x - p, y - q) > 0.26 for p, q in pts):
            pts.append((x, y))
    for x, y in pts:
        w.add_circle((x, y), 0.12, restitution=0.6, velocity=(rng.uniform(-1, 1), 0.0), mass=0.05)
    return w


@pytest.mark.parametrize("seed", [2, 3])
def test_pile_settles(engine, seed: int) -> None:
    """40 balls (e = 0.6, walls 0.8) dropped into a box: at every frame no two overlap beyond the
    tolerance (exact geometry) and the energy never rises (beyond the rule's bounded parting
    speeds); within 5 s every ball is asleep, after a bounded number of events."""
    w = _pile(engine, seed=seed)
    e0 = prev = w.energy(0.0)
    tc, g, m = 1e-3, 9.81, 0.05
    allowance = 40 * m * (g * tc / 2) ** 2  # rule 2's minimum parting speeds, all at once
    for k in range(1, 101):
        t = k * 0.05
        w.step_to(t, events=False)
        e = w.energy()
        assert e <= prev + allowance + 1e-12 * e0
        prev = e
        assert_apart(w)
    assert all(w.asleep(b.id) for b in w.bodies if b.kind == "dynamic")
    assert w.energy() < e0
    assert w.stats()["events"] < 40 * 5000
    done = w.stats()["events"]
    w.step_to(60.0)
    assert w.stats()["events"] == done  # asleep: nothing more happens


def test_asleep_ball_wakes_when_hit(engine) -> None:
    g = 9.81
    w = engine.World(gravity=(0.0, -g))
    w.add_segment((-5.0, 0.0), (5.0, 0.0))
    sleeper = w.add_circle((0.0, 0.1), 0.1, restitution=0.5)
    w.step_to(1.0)
    assert w.asleep(sleeper)
    w.add_circle((-3.0, 0.1), 0.1, velocity=(2.0, 0.0), restitution=0.5)
    events = w.step_to(3.0)
    kinds = [ev.kind for ev in events]
    assert "wake" in kinds and not w.asleep(sleeper)
    assert w.velocity(sleeper, 3.0)[0] > 0.5
