"""Bodies the contact solver holds, served by a room."""

from __future__ import annotations

import json
import math

from max2code.engine.limits import CONTACT_STEP
from max2code.engine.scenefile import Scene
from max2code.engine.world import World
from max2code.server.room import Room

from .client import Client

G = 9.81
H = CONTACT_STEP
VIEW = (-2.0, -0.5, 2.0, 4.5)


def serve(w: World, rate: float = 0.0) -> tuple[Room, Client, list[str], list[float]]:
    clock = [0.0]
    room = Room("held", Scene(name="held", bodies=(), view=VIEW), (), clock=lambda: clock[0],
                tolerance=0.0, world=w, rate=rate)
    inbox: list[str] = []
    _, text = room.join(inbox.append, "a", events=False)
    return room, Client.fed(text), inbox, clock



def test_a_world_that_starts_in_contact_is_stepped():
    """A ball put down on the floor has its first event at 0, the room's own time: the room
    stepped nothing at its time (advance returned) and its loop woke at 0 for ever."""
    w = World(gravity=(0.0, -G))
    w.add_segment((-50, 0), (50, 0), friction=0.5)
    ball = w.add_circle((0, 0.1), 0.1, velocity=(0.5, 0), omega=-5.0, restitution=0, friction=0.5)
    room, c, inbox, clock = serve(w, rate=60.0)
    wakes = 0
    while (t := room.next_wake()) <= 1.0 and wakes < 10_000:
        wakes += 1
        clock[0] = t
        room.advance(t)
    assert w.time > 0.99 and w.solving(ball), (wakes, w.time)
