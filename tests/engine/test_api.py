"""The Python API: building worlds, stepping, callbacks at their event's time, input and timer
events, exact poses at any time, errors."""

from __future__ import annotations

import math

import pytest


def test_poses_are_exact_ballistics(engine) -> None:
    w = engine.World(gravity=(0.0, -9.81))
    b = w.add_circle((1.0, 2.0), 0.1, velocity=(3.0, 4.0))
    w.step_to(0.25)
    for t in (0.25, 0.5, 1.0):
        x, y, a = w.pose(b, t)
        assert x == pytest.approx(1.0 + 3.0 * t, rel=1e-15)
        assert y == pytest.approx(2.0 + 4.0 * t - 9.81 * t * t / 2, rel=1e-15)
        assert a == 0.0
    assert w.velocity(b, 1.0)[:2] == pytest.approx((3.0, 4.0 - 9.81), rel=1e-15)
    assert w.poses(0.5)[b] == w.pose(b, 0.5)


def test_callbacks_run_at_their_event_time(engine) -> None:
    """A callback sees the world at the event's time and may change it (an input event)."""
    w = engine.World()
    w.add_segment((2.0, -1.0), (2.0, 1.0))
    ball = w.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0), name="ball")
    seen = []

    def hit(world, ev):
        seen.append((ev.time, world.time, world.pose(ball)[0], world.velocity(ball)[0]))
        if len(seen) == 1:
            world.set_velocity(ball, (0.0, 2.0))  # after the first bounce, go up instead

    w.on_collision(hit)
    events = w.step_to(5.0)
    assert len(events) == 1 and events[0].kind == "collision"
    t, now, x, vx = seen[0]
    assert t == now == pytest.approx(1.5, rel=1e-15) and x == pytest.approx(1.5, rel=1e-15)
    assert vx == pytest.approx(-1.0, rel=1e-15)   # the bounce happened before the callback
    assert w.pose(ball) == pytest.approx((1.5, 2.0 * 3.5, 0.0), rel=1e-15)
    assert w.body("ball").id == ball


def test_timers(engine) -> None:
    w = engine.World()
    ball = w.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0))
    fired = []
    w.add_timer(0.75, lambda world, ev: (fired.append(world.time), world.set_velocity(ball, (0.0, 0.0))))
    k = w.add_timer(0.5)
    events = w.step_to(2.0)
    assert [(e.kind, e.time) for e in events] == [("timer", 0.5), ("timer", 0.75)]
    assert events[0].a == k
    assert fired == [0.75]
    assert w.pose(ball)[0] == pytest.approx(0.75, rel=1e-15)
    with pytest.raises(engine.EngineError):
        w.add_timer(1.0)  # in the past


@pytest.mark.parametrize("kw,words", [
    (dict(restitution=1.5), "restitution"),
    (dict(radius=-1.0), "radius"),
    (dict(kind="solid"), "kind"),
    (dict(mass=-1.0), "mass"),
])
def test_bad_bodies_refused(engine, kw, words: str) -> None:
    w = engine.World()
    args = dict(radius=0.5)
    args.update(kw)
    radius = args.pop("radius")
    with pytest.raises(engine.EngineError, match=words):
        w.add_circle((0.0, 0.0), radius, **args)


def test_non_convex_polygon_refused_by_the_core(engine) -> None:
    w = engine.World()
    with pytest.raises(engine.EngineError, match="convex"):
        w.add_polygon([(0, 0), (2, 0), (1, 0.5), (1, 2)], kind="static")


def test_body_info(engine) -> None:
    w = engine.World()
    i = w.add_polygon([(0.0, 0.0), (3.0, 0.0), (0.0, 3.0)], position=(10.0, 0.0), kind="static",
                      name="tri", color="#102030")
    info = w.bodies[i]
    assert info.shape == "polygon" and info.kind == "static" and math.isinf(info.mass)
    assert info.vertices == ((0.0, 0.0), (3.0, 0.0), (0.0, 3.0)) and info.color == "#102030"
    assert w.pose(i) == (10.0, 0.0, 0.0)
    c = w.add_circle((1.0, 1.0), 0.5, mass=2.0)
    assert w.bodies[c].mass == 2.0 and w.bodies[c].inertia == pytest.approx(0.25)


def test_stats_and_events_per_kind(engine) -> None:
    w = engine.World(cell_size=1.0)
    w.add_circle((0.0, 0.0), 0.1, velocity=(1.0, 0.0))
    w.add_circle((20.0, 0.0), 0.1)
    w.step_to(30.0)
    s = w.stats()
    assert s["collisions"] == 1 and s["cell_crossings"] > 10
    assert s["solves_by_degree"]


def test_stepping_backwards_does_nothing(engine) -> None:
    w = engine.World()
    b = w.add_circle((0.0, 0.0), 0.1, velocity=(1.0, 0.0))
    w.step_to(2.0)
    assert w.step_to(1.0) == [] and w.time == 2.0 and w.pose(b)[0] == 2.0


def test_per_body_gravity(engine) -> None:
    """A body's own gravity overrides the world's: a balloon rises while a stone falls."""
    w = engine.World(gravity=(0.0, -9.81))
    stone = w.add_circle((0.0, 10.0), 0.1)
    balloon = w.add_circle((5.0, 10.0), 0.1, gravity=(0.0, 2.0))
    w.step_to(1.0)
    assert w.pose(stone)[1] == pytest.approx(10.0 - 9.81 / 2, rel=1e-15)
    assert w.pose(balloon)[1] == pytest.approx(10.0 + 1.0, rel=1e-15)
    assert w.energy() == pytest.approx(w.energy(1.0))


def test_deterministic_log_across_processes(engine, tmp_path) -> None:
    """`max2code sim` twice on the pinball (rotation, polygons, gravity, the rest rule): the
    same event log, byte for byte."""
    import subprocess
    import sys
    from conftest import ROOT
    logs = []
    for k in range(2):
        out = tmp_path / f"e{k}.jsonl"
        r = subprocess.run([sys.executable, "-m", "max2code", "sim", str(ROOT / "examples" / "scenes" / "pinball.toml"),
                            "--until", "4", "--events", str(out)], capture_output=True, text=True, cwd=ROOT,
                           timeout=600)
        assert r.returncode == 0, r.stderr
        logs.append(out.read_bytes())
    assert logs[0] == logs[1] and logs[0].count(b"\n") > 100
