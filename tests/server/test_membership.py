"""Bodies removed and added while the world runs (protocol version 2, docs/server.md): a
client's reconstructed set of bodies is the server world's alive set after every message, a
removed body never appears again, added bodies come with their shape and segment, and a late
joiner agrees."""

from __future__ import annotations

import asyncio
import json

import pytest

from max2code.server import protocol, wire
from max2code.server.app import Options
from max2code.server.room import Room

from . import bricks
from .client import Client
from .conftest import Running


class Clock:
    """The room's clock, moved by the test."""

    def __init__(self) -> None:
        self.t = 0.0

    def __call__(self) -> float:
        return self.t


def check_poses(c: Client, world, t: float) -> None:
    for i in c.bodies:
        assert c.pose(i, t) == pytest.approx(world.pose(i, t), abs=1e-7), (i, t)


@pytest.mark.parametrize("tolerance", [0.0, None])
def test_after_every_message_the_client_holds_the_alive_set(tolerance):
    clock = Clock()
    room = Room("r", bricks.scene(), (), clock=clock, tolerance=tolerance, world=bricks.build())
    inbox: list[str] = []
    first, text = room.join(inbox.append, "a")
    c = Client.fed(text)
    assert set(c.bodies) == bricks.alive(room.world) and c.world["v"] == protocol.VERSION
    late = None
    gone: set[int] = set()
    seen_rm = seen_add = 0
    for k in range(1, 401):
        clock.t = k * 0.01
        room.advance(clock.t)
        for m in map(json.loads, inbox):
            c.apply(m)
            gone.update(m.get("rm", []))
            seen_rm += len(m.get("rm", []))
            seen_add += len(m.get("add", []))
            for b in m.get("add", []):
                assert b["id"] not in gone and {"shape", "fill", "name"} <= set(b)
                assert b["id"] in {s[0] for s in wire.expanded(m, c.g)}   # an added body comes with its segment
        inbox.clear()
        alive = bricks.alive(room.world)
        assert set(c.bodies) == alive == set(c.segs), clock.t
        assert not gone & set(c.bodies)
        if tolerance == 0.0:
            check_poses(c, room.world, clock.t)
        if k == 150:   # a late joiner, after removals and additions
            late_inbox: list[str] = []
            _, text = room.join(late_inbox.append, "late")
            late = Client.fed(text)
            assert set(late.bodies) == bricks.alive(room.world)
        if late is not None:
            for m in map(json.loads, late_inbox):
                late.apply(m)
            late_inbox.clear()
            assert set(late.bodies) == set(c.bodies)
            if tolerance == 0.0:
                check_poses(late, room.world, clock.t)
    # the run did what it is for: bricks removed, chips and the second ball added, a chip
    # removed again after its addition
    names = {b["name"] for b in c.bodies.values()}
    assert seen_rm >= 3 and seen_add >= 3, (seen_rm, seen_add)
    assert "ball2" in names and "chip0" not in names


def test_over_websockets_with_a_late_joiner():
    """The same through the server: replayed against an independent world at every message's
    time, the client's bodies are the alive set then."""
    running = Running(Options(bricks.scene(), (), tolerance=0.0, world=bricks.build))
    try:
        async def go():
            first = await Client.join(running.url)
            await first.receive(1.5)
            late = await Client.join(running.url)
            await asyncio.gather(first.receive(1.5), late.receive(1.5))
            return first, late
        first, late = asyncio.run(go())
    finally:
        running.stop()
    reference = bricks.build()
    bodies = {b["id"] for b in first.world["bodies"]}
    reference.step_to(first.world["t"])
    assert bodies == bricks.alive(reference)
    gone: set[int] = set()
    removals = 0
    for m in first.messages:
        if m["type"] != "ev":
            continue
        bodies -= set(m.get("rm", []))
        gone |= set(m.get("rm", []))
        removals += len(m.get("rm", []))
        bodies |= {b["id"] for b in m.get("add", [])}
        assert not gone & bodies
        reference.step_to(m["t"])
        assert bodies == bricks.alive(reference), m["t"]
    assert removals >= 2
    assert set(first.bodies) == bodies
    # the late joiner, at the end, holds what the first client holds, pose for pose
    assert set(late.bodies) == set(first.bodies)
    t = max(t for _, t in first.segs.values())
    for i in late.bodies:
        assert late.pose(i, t) == pytest.approx(first.pose(i, t), abs=1e-9)
    # and it joined with the bodies alive at its join, none removed before it
    at_join = bricks.build()
    at_join.step_to(late.world["t"])
    assert late.world["t"] > 1.0 and {b["id"] for b in late.world["bodies"]} == bricks.alive(at_join)
    assert len(at_join.bodies) > len(bricks.alive(at_join))
