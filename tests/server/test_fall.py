"""Protocol version 4's `fall` list (docs/server.md): a segment whose acceleration is the world's
gravity goes without it. The split must lose nothing (a client holds the same segments), must
be checked against the engine itself, and must pay off where bodies fall."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from max2code.engine.limits import CONTACT_STEP
from max2code.engine.scenefile import build_world, load
from max2code.server import protocol, wire
from max2code.server.room import Room

from .client import Client

ROOT = Path(__file__).resolve().parents[2]
PILE = ROOT / "examples" / "scenes" / "pile.toml"
ARENA = ROOT / "examples" / "scenes" / "arena.toml"

value = st.one_of(st.just(0), st.integers(-5, 5),
                  st.floats(-1e6, 1e6, allow_nan=False).map(protocol.number))


def trimmed(i: int, values: list) -> list:
    """A segment as wire.segment writes it: trailing zeros off, at least x, y, angle kept."""
    values = list(values)
    while len(values) > 3 and values[-1] == 0:
        values.pop()
    return [i] + values


@settings(max_examples=300, deadline=None)
@given(st.lists(st.lists(value, min_size=8, max_size=8), max_size=12),
       st.tuples(value, value), st.booleans())
def test_split_then_expanded_gives_back_every_segment(rows, g, as_g):
    if as_g:   # (half the time most segments do fall with g)
        rows = [r[:6] + list(g) for r in rows]
    segs = [trimmed(i, r) for i, r in enumerate(rows)]
    explicit, fall = wire.split(segs, g)
    message = {"seg": explicit, "fall": fall}
    assert sorted(wire.expanded(message, g)) == sorted(segs)
    for seg in fall:            # a fall segment carries no acceleration, and no trailing zero
        assert 4 <= len(seg) <= 7 and (len(seg) == 4 or seg[-1] != 0)
    if list(g) != [0, 0]:       # and every segment accelerating at g was split off
        assert all((s + [0] * 9)[7:9] != list(g) for s in explicit)
    else:
        assert fall == []


def replay(path: Path, until: float) -> tuple[dict, list[dict]]:
    clock = [0.0]
    room = Room("fall", load(path), (), clock=lambda: clock[0])
    inbox: list[str] = []
    _, world = room.join(inbox.append, "a")
    while (t := room.next_wake()) <= until:
        clock[0] = t
        room.advance(t)
    return json.loads(world), [json.loads(m) for m in inbox]


def test_a_falling_pile_sends_fall_segments_that_give_the_engines_poses():
    world, messages = replay(PILE, 1.5)
    assert world["v"] == protocol.VERSION == 6 and world["g"] == [0, -9.81]
    c = Client(None)
    c.start(world)
    reference = build_world(load(PILE))      # a world of its own: the oracle
    # a body the contact solver holds is sent as its chord, within the hop and the slop
    # (docs/server.md, "Bodies the contact solver holds"); every other body exactly
    held = reference.contact_slop + 9.81 * CONTACT_STEP ** 2 / 8
    falls = explicit = 0
    for m in messages:
        c.apply(m)
        if m["t"] <= 0.5:    # (falling: then the solver holds its bodies, whose chords do not)
            falls += len(m.get("fall", []))
            explicit += len(m["seg"])
        reference.step_to(m["t"], events=False)
        for body in c.bodies:
            bound = held * (1 + 1e-9) if reference.solving(body) else 1e-7
            assert c.pose(body, m["t"]) == pytest.approx(reference.pose(body, m["t"]), abs=bound)
    assert falls > 2 * explicit and falls > 0, (falls, explicit)
    # what it saves the page (no event lists) while the pile falls: the same messages with
    # every segment explicit, as version 3 sent them
    page = [{k: v for k, v in m.items() if k != "ev"} for m in messages if m["t"] <= 0.5]
    old = sum(len(protocol.encode({k: v for k, v in m.items() if k != "fall"}
                                  | {"seg": wire.expanded(m, world["g"])})) for m in page)
    new = sum(len(protocol.encode(m)) for m in page)
    assert new < 0.93 * old, (new, old)   # (measured: 0.90)


def test_a_world_without_gravity_sends_no_g_and_no_fall():
    world, messages = replay(ARENA, 2.0)
    assert "g" not in world and "fall" not in world
    assert messages and all("fall" not in m for m in messages)
