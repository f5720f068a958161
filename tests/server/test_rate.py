"""What a room leaves out (protocol version 3, docs/server.md "What is sent"): at most `rate`
messages a second, each body's latest segment only, no segment equal to what clients hold, each
event (kind, a, b) once per message with a count, noise below wire.Zero as 0; and none of it
costs exactness: after every message a client's segments give the engine's poses."""

from __future__ import annotations

import json
import math

import pytest

from max2code.engine.limits import CONTACT_STEP
from max2code.engine.scenefile import load
from max2code.engine.world import Event
from max2code.server import wire
from max2code.server.room import Room, _events

from .client import Client
from .conftest import ROOT

SCENES = ROOT / "examples" / "scenes"


def replay(name: str, until: float, rate: float) -> tuple[Room, Client, list[tuple[float, dict]]]:
    """The room woken at each queued event (as the server is), a client fed in-process, and
    every message with the room's clock when it went out. After each message the client's
    segments are checked against the engine at that clock time."""
    clock = [0.0]
    room = Room("r", load(SCENES / f"{name}.toml"), (), clock=lambda: clock[0], tolerance=0.0, rate=rate)
    inbox: list[str] = []
    _, text = room.join(inbox.append, "a")
    c = Client.fed(text)
    view = c.world["view"]
    scale = max(view[2] - view[0], view[3] - view[1])
    chord_bound = (room.world.contact_slop + 9.81 * CONTACT_STEP ** 2 / 8) * (1 + 1e-9)
    out = []
    while (t := room.next_wake()) <= until:
        clock[0] = t
        room.advance(t)
        for m in map(json.loads, inbox):
            for seg in wire.expanded(m, c.g):    # never a segment clients already hold
                held, t0 = c.segs[seg[0]]
                assert seg != wire.segment(seg[0], wire.motion(held, t0), m["t"]), (m["n"], seg)
            c.apply(m)
            out.append((t, m))
            assert m["t"] <= t
            if not room.due:        # (nothing owed: the client holds the engine's state)
                c.checked = getattr(c, "checked", 0) + 1
                for i in c.bodies:   # (a body the contact solver holds: within its chord's bound)
                    bound = chord_bound if room.world.solving(i) else 1e-9 * scale
                    assert c.pose(i, t) == pytest.approx(room.world.pose(i, t), abs=bound), (i, t)
        inbox.clear()
    return room, c, out


@pytest.mark.parametrize("name,until", [("pile", 1.5), ("bullet", 0.5)])
def test_a_burst_costs_at_most_rate_messages_and_stays_exact(name, until):
    room, c, out = replay(name, until, 60.0)
    sent = [t for t, _ in out]
    assert all(b - a >= 1 / 60 - 1e-12 for a, b in zip(sent, sent[1:]))
    assert len(out) <= until * 60 + 1
    _, _, out0 = replay(name, until, 0.0)       # every step's changes at once: as exact
    assert len(out0) > 3 * len(out)
    assert c.checked >= len(out) // 2        # (the poses were compared that often)
    for _, m in out:             # events: each (kind, a, b) once, counts where repeated
        keys = [tuple(e[:3]) for e in m["ev"]]
        assert len(keys) == len(set(keys))
        assert all(len(e) in (3, 4) or (len(e) == 5 and e[4] > 1) for e in m["ev"])
        assert all(e[3] <= 0 for e in m["ev"] if len(e) > 3)


def test_an_isolated_event_is_not_held():
    """arena's collisions are far apart: the rate limit changes nothing, message for message."""
    _, _, out = replay("arena", 6.0, 60.0)
    _, _, out0 = replay("arena", 6.0, 0.0)
    assert len(out) >= 5 and [m for _, m in out] == [m for _, m in out0]
    assert all(m["t"] == t for t, m in out)      # each sent at its event's time


def ev(t: float, kind: str, a: int, b: int) -> Event:
    return Event(t, kind, a, b, (1.0, 0.0), (0.0, 0.0), 1.0, 1.0)


def test_events_once_per_kind_and_pair_latest_time_and_count():
    drawn = [ev(0.1, "collision", 1, 2), ev(0.2, "collision", 3, 4), ev(0.3, "collision", 1, 2),
             ev(0.35, "rest", 1, 0), ev(0.4, "collision", 5, 6), ev(0.5, "collision", 1, 2)]
    assert _events(drawn, {1, 3}, 0.5) == [[1, 3, 4, -0.3], [2, 1, 0, -0.15], [1, 1, 2, 0, 3]]
    assert _events(drawn, set(), 0.5) == []         # nobody's segment sent: nothing seen


def test_zero_sends_noise_as_0_and_bounds_the_error():
    zero = wire.Zero.of([0.0, 0.0, 2.0, 1.0])
    assert (zero.length, zero.angle) == (2e-12, 1e-12)
    m = (1.0, 0.5, 1e-13, -1.2e-15, 0.25, 3e-13, 5e-17, 0.0, -1e-13)
    assert wire.segment(7, m, 1.0, zero) == [7, 0.5, 0, 0, 0.25]
    assert wire.segment(7, m, 1.0) == [7, 0.5, 1e-13, -1.2e-15, 0.25, 3e-13, 5e-17, 0, -1e-13]
    seg = wire.segment(7, m, 1.0, zero)
    for s in (0.0, 1.0, 10.0):
        a, b = wire.pose(seg, 1.0 + s, 1.0), wire.pose(wire.segment(7, m, 1.0), 1.0 + s, 1.0)
        bound = (1 + s + s * s / 2)
        assert abs(a[0] - b[0]) <= 2e-12 * bound and abs(a[1] - b[1]) <= 2e-12 * bound
        assert abs(a[2] - b[2]) <= 1e-12 * bound
    assert wire.Zero.of([0, 0, math.inf, 1]).length == 0.0
