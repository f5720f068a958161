"""Callbacks per body, per pair and per collision type, pre-solve vetoes (one-way platforms),
sensors, separate events and user data in events (issue 35). Times are closed forms."""

from __future__ import annotations

import math

import pytest


def _one_way(engine):
    w = engine.World(gravity=(0.0, -10.0), rest_speed=-1.0)
    plat = w.add_segment((-1.0, 1.0), (1.0, 1.0), collision_type=2, data="platform")
    ball = w.add_circle((0.0, 0.0), 0.1, velocity=(0.0, 6.0), collision_type=1, data="ball")
    return w, plat, ball


def test_one_way_platform_by_pre_solve_veto(engine) -> None:
    """Thrown up through a thin platform (the contact from below is vetoed), the ball falls
    back onto it and bounces there: y = 6 t - 5 t^2 meets 0.9 going up, 1.1 coming down."""
    w, plat, ball = _one_way(engine)
    seen = []

    def from_above(world, ev):
        seen.append((ev.kind, ev.time, ev.data))
        n = ev.normal if ev.a == ball else (-ev.normal[0], -ev.normal[1])
        return n[1] < 0          # keep it only when the ball moves down onto it

    w.collision_handler(1, 2).pre_solve = from_above
    events = w.step_to(1.5)
    up, down = (6 - math.sqrt(36 - 4 * 5 * 0.9)) / 10, (6 + math.sqrt(36 - 4 * 5 * 1.1)) / 10
    assert [k for k, _, _ in seen] == ["presolve", "presolve"]
    assert seen[0][1] == pytest.approx(up, rel=1e-12) and seen[1][1] == pytest.approx(down, rel=1e-12)
    assert seen[0][2] == ("ball", "platform") or seen[0][2] == ("platform", "ball")
    assert [(e.kind, e.time) for e in events] == [("collision", pytest.approx(down, rel=1e-12))]
    assert w.velocity(ball)[1] == pytest.approx(-10 * (1.5 - down) + math.sqrt(14.0), rel=1e-9)


def test_pre_solve_may_not_change_the_world(engine) -> None:
    w, plat, ball = _one_way(engine)
    w.on_pre_solve(ball, lambda world, ev: world.remove(plat))
    with pytest.raises(engine.EngineError, match="pre-solve"):
        w.step_to(1.0)


def test_sensor_reports_and_never_responds(engine) -> None:
    """A coin (a static sensor) reports the ball at the exact time, the ball flies on; the
    callback collects (removes) it."""
    w = engine.World()
    coin = w.add_circle((3.0, 0.0), 0.5, kind="static", sensor=True, data="coin")
    ball = w.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0))
    wall = w.add_segment((8.0, -1.0), (8.0, 1.0))
    got = []

    def collect(world, ev):
        got.append((ev.kind, ev.time, ev.data))
        world.remove(coin)

    w.on_collision(collect, body=coin)
    events = w.step_to(10.0)
    assert got == [("sensor", 2.0, (None, "coin"))]
    assert [(e.kind, e.time, e.b) for e in events] == [("sensor", 2.0, coin), ("collision", 7.5, wall)]
    assert w.velocity(ball)[0] == -1.0


def test_sensor_passes_through_until_met_again(engine) -> None:
    """A kept sensor: entered and left on the way in; a second pass (after the wall) is
    reported again; no response either time."""
    w = engine.World()
    zone = w.add_polygon([(-0.5, -2.0), (0.5, -2.0), (0.5, 2.0), (-0.5, 2.0)], kind="static",
                         position=(3.0, 0.0), sensor=True)
    ball = w.add_circle((0.0, 0.0), 0.25, velocity=(1.0, 0.0))
    w.add_segment((6.0, -1.0), (6.0, 1.0))
    events = [(e.kind, e.time) for e in w.step_to(12.0)]
    assert [k for k, _ in events] == ["sensor", "sensor_leave", "collision", "sensor", "sensor_leave"]
    assert [t for _, t in events] == pytest.approx([2.25, 3.75, 5.75, 7.75, 9.25], rel=1e-12)


def test_callbacks_per_body_per_pair_and_type(engine) -> None:
    w = engine.World()
    a = w.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0), collision_type=1)
    b = w.add_circle((3.0, 0.0), 0.5, collision_type=2)
    c = w.add_circle((10.0, 0.0), 0.5, collision_type=3)
    log = []
    w.on_collision(lambda world, e: log.append(("every", e.a, e.b)))
    w.on_collision(lambda world, e: log.append(("body c", e.a, e.b)), body=c)
    w.on_collision_with(b, c, lambda world, e: log.append(("pair bc", e.a, e.b)))
    w.collision_handler(1, 2).post_solve = lambda world, e: log.append(("type 1-2", e.a, e.b))
    w.collision_handler(2).post_solve = lambda world, e: log.append(("type 2-any", e.a, e.b))
    w.step_to(20.0)
    assert log == [("every", a, b), ("type 1-2", a, b), ("type 2-any", a, b),
                   ("every", b, c), ("body c", b, c), ("pair bc", b, c), ("type 2-any", b, c)]


def test_separate_ends_a_sustained_contact(engine) -> None:
    """A ball landing without bounce slides along a floor; leaving its end is `separate`."""
    w = engine.World(gravity=(0.0, -10.0))
    w.add_segment((-1.0, 0.0), (1.0, 0.0), collision_type=2)
    ball = w.add_circle((0.0, 1.0), 0.1, velocity=(1.0, 0.0), restitution=0.0, collision_type=1)
    ends = []
    w.collision_handler(1, 2).separate = lambda world, e: ends.append((e.time, e.a))
    w.step_to(2.0)
    assert ends == [(pytest.approx(1.0, rel=1e-12), ball)]
    assert w.pose(ball)[1] < 0


def test_timer_data_and_errors_in_callbacks(engine) -> None:
    w = engine.World()
    seen = []
    w.add_timer(1.0, lambda world, e: seen.append(e.data), data={"spawn": 3})
    w.step_to(2.0)
    assert seen == [({"spawn": 3}, None)]
    w2, plat, ball = _one_way(engine)

    def broken(world, ev):
        raise ValueError("in pre-solve")

    w2.on_pre_solve(ball, broken)
    with pytest.raises(ValueError, match="in pre-solve"):
        w2.step_to(1.0)
