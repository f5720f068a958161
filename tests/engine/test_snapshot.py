"""Snapshots of a World (issue 35): pickle and copy.deepcopy give a world that goes on with the
same future events, bit for bit; restore rolls back; damaged bytes are refused."""

from __future__ import annotations

import copy
import pickle

import pytest
from hypothesis import given, settings, strategies as st


def _scene(engine, seed: int):
    import random
    rnd = random.Random(seed)
    w = engine.World(gravity=(0.0, -9.81))
    for a, b in (((-5, 0), (5, 0)), ((-5, 0), (-5, 10)), ((5, 0), (5, 10))):
        w.add_segment(a, b)
    taken = [(0.0, 5.0, 0.4), (0.0, 0.5, 0.3), (2.0, 2.0, 0.4)]   # the box, kinematic, sensor
    while len(taken) < 15:                                       # balls that start apart
        x, y = rnd.uniform(-4, 4), rnd.uniform(1, 9)
        if all((x - a) ** 2 + (y - b) ** 2 > (0.3 + r) ** 2 for a, b, r in taken):
            taken.append((x, y, 0.2))
            w.add_circle((x, y), 0.2, restitution=rnd.uniform(0.5, 1),
                         velocity=(rnd.uniform(-3, 3), rnd.uniform(-3, 3)))
    w.add_polygon([(-0.3, -0.2), (0.3, -0.2), (0.3, 0.2), (-0.3, 0.2)], position=(0.0, 5.0), omega=3.0)
    w.add_circle((0.0, 0.5), 0.3, kind="kinematic", velocity=(0.5, 0.0))
    w.add_circle((2.0, 2.0), 0.4, kind="static", sensor=True)
    w.add_timer(2.5)
    return w


def _log(events):
    return [(e.time, e.kind, e.a, e.b, e.normal, e.point, e.speed, e.impulse) for e in events]


@settings(max_examples=12, deadline=None)
@given(seed=st.integers(0, 10_000), t=st.floats(0.0, 2.0))
def test_pickle_and_deepcopy_reproduce_the_future(engine, seed: int, t: float) -> None:
    w = _scene(engine, seed)
    w.step_to(t)
    pickled, copied = pickle.dumps(w), copy.deepcopy(w)
    future = _log(w.step_to(4.0))
    assert _log(pickle.loads(pickled).step_to(4.0)) == future
    assert _log(copied.step_to(4.0)) == future


def test_restore_rolls_back_and_copies_are_independent(engine) -> None:
    w = _scene(engine, 1)
    w.step_to(0.5)
    snap = copy.deepcopy(w)
    ball = 3
    w.remove(ball)
    w.set_velocity(4, (0.0, 9.0))
    changed = _log(w.step_to(3.0))
    w.restore(snap)
    assert w.time == 0.5 and w.alive(ball) and w.bodies[ball].alive
    again = _log(w.step_to(3.0))
    assert again != changed
    assert again == _log(copy.deepcopy(snap).step_to(3.0))
    assert snap.time == 0.5                       # the snapshot itself did not move


def test_callbacks_survive_a_deepcopy(engine) -> None:
    w = engine.World()
    wall = w.add_segment((2.0, -1.0), (2.0, 1.0))
    w.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0))
    seen = []
    w.on_collision(lambda world, e: (seen.append((e.time, world is w)), world.remove(wall)))
    c = copy.deepcopy(w)
    c.step_to(5.0)
    assert seen == [(1.5, False)] and not c.alive(wall) and w.alive(wall)


def test_damaged_snapshot_refused(engine) -> None:
    w = _scene(engine, 2)
    w.step_to(0.3)
    state = w.__getstate__()
    for core in (state["_core"][:-8], state["_core"][:40], b"", state["_core"] + b"x"):
        bad = dict(state, _core=core)
        with pytest.raises(engine.EngineError, match="snapshot"):
            engine.World.__new__(engine.World).__setstate__(bad)
