"""World.motions() and World.next_time(): what `max2code serve` sends and when it wakes."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

SCENES = Path(__file__).resolve().parents[2] / "examples" / "scenes"


def _pose(m, t):
    t0, x, y, th, vx, vy, w, ax, ay = m
    s = t - t0
    return (x + s * (vx + 0.5 * ax * s), y + s * (vy + 0.5 * ay * s), th + w * s)


@pytest.mark.parametrize("name", ["pinball.toml", "arena.toml", "pile.toml"])
def test_segments_give_poses_and_counters_mark_changes(name) -> None:
    from max2code.engine.scenefile import build_world, load

    w = build_world(load(SCENES / name))
    motions, counters = w.motions()
    solving = {i for i in range(len(w.bodies)) if w.solving(i)}
    for step in range(1, 40):
        t = step * 0.05
        events = w.step_to(t)
        new, new_counters = w.motions()
        changed = {i for i, (a, b) in enumerate(zip(counters, new_counters)) if a != b}
        # a body whose counter kept still moves on its old segment: same pose at t
        for i in range(len(new)):
            assert new[i][0] <= t
            assert _pose(new[i], t) == pytest.approx(w.pose(i, t), abs=1e-9)
            if i not in changed:
                assert _pose(motions[i], t) == pytest.approx(w.pose(i, t), abs=1e-9)
        touched = {e.a for e in events} | {e.b for e in events if e.b >= 0}
        # ... or the contact solver's ticks: a body in it before or after (it joins only at an
        # event; it leaves after ticks with no contact) (the server relies on counters)
        now_solving = {i for i in range(len(new)) if w.solving(i)}
        assert changed <= touched | solving | now_solving
        solving = now_solving
        # every reported event's bodies that took an impulse changed
        assert {e.a for e in events if e.kind == "collision" and w.bodies[e.a].kind == "dynamic"
                and e.impulse != 0} <= changed
        motions, counters = new, new_counters


def test_next_time_is_a_lower_bound_on_the_next_event() -> None:
    from max2code.engine import World

    w = World()
    w.add_segment((2.0, -1.0), (2.0, 1.0))
    w.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0))
    assert w.next_time() <= 1.5
    events = w.step_to(w.next_time())
    while not events:
        events = w.step_to(w.next_time())
    assert events[0].time == pytest.approx(1.5)
    still = World()
    still.add_circle((0.0, 0.0), 0.5)
    assert still.next_time() >= 1e3     # nothing soon (inf, or the core's far horizon)
    k = still.add_timer(3.0)
    assert still.next_time() == 3.0 and k >= 0
