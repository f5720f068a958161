"""The protocol over real WebSockets on 127.0.0.1 (docs/server.md): what a client receives,
that it suffices to draw the engine's exact state, input and its refusals, rooms."""

from __future__ import annotations

import asyncio
import json
import urllib.request

import pytest
from websockets.asyncio.client import connect
from websockets.exceptions import InvalidStatus

from max2code.engine.scenefile import build_world, load
from max2code.server import protocol, wire

from .client import Client
from .conftest import ARENA, ROOT, start


def run(coro):
    return asyncio.run(coro)


def test_join_gets_the_world_and_segments_give_the_engines_poses(arena):
    async def go():
        c = await Client.join(arena.url)
        w = c.world
        assert w["v"] == protocol.VERSION == 6 and w["you"] == [4] and len(w["bodies"]) == 12
        assert w["bodies"][4]["name"] == "player1" and w["bodies"][4]["fill"] == "#c44e52"
        assert w["bodies"][4]["shape"] == {"c": [0, 0], "r": 0.12}
        assert w["bodies"][8]["shape"]["p"][0] == [-0.08, -0.08]      # puck3, a box
        await c.receive(2.5)
        return c
    c = run(go())
    # no input was given: an independent world from the same scene, stepped to any time the
    # client has heard of, is where the client's segments put every body
    reference = build_world(load(ARENA))
    t_last = max(t for _, t in c.segs.values())
    assert t_last > 1.0
    for k in range(1, 11):
        t = t_last * k / 10
        reference.step_to(t)
        for body, (seg, t0) in c.segs.items():
            if t0 <= t:   # (a body changed after t holds a segment from later on)
                assert c.pose(body, t) == pytest.approx(reference.pose(body, t), abs=1e-7), (body, t)
    kinds = {e[0] for m in c.messages if m["type"] == "ev" for e in m["ev"]}
    assert kinds <= {1, 2, 3} and 1 in kinds


def test_every_event_message_matches_the_engine_at_its_time(arena):
    """Replay: apply each message in turn and compare with a reference world at that time."""
    async def go():
        c = await Client.join(arena.url)
        await c.receive(3.0)
        return c
    c = run(go())
    events = [m for m in c.messages if m["type"] == "ev"]
    assert len(events) >= 3
    reference = build_world(load(ARENA))
    state = {s[0]: (s, c.world["t"]) for s in wire.expanded(c.world, c.g)}
    for m in events:
        for s in wire.expanded(m, c.g):
            state[s[0]] = (s, m["t"])
        reference.step_to(m["t"])
        for body, (seg, t0) in state.items():
            assert wire.pose(seg, m["t"], t0) == pytest.approx(reference.pose(body, m["t"]), abs=1e-7)
        # each message names the bodies its events changed, and no others
        named = {e[1] for e in m["ev"]} | {e[2] for e in m["ev"] if e[2] >= 0}
        assert {s[0] for s in wire.expanded(m, c.g)} <= named


def test_a_client_may_ask_for_no_event_lists(arena):
    """hello's events: false (the page's): the same messages, the same segments, no "ev"."""
    async def go():
        full = await Client.join(arena.url, play=False)
        bare = await Client.join(arena.url, play=False, events=False)
        await asyncio.gather(full.receive(2.5), bare.receive(2.5))
        return full, bare
    full, bare = run(go())
    got = [m for m in full.messages if m["type"] == "ev" and m["n"] > bare.world["n"]]
    assert len(got) >= 2 and any(m["ev"] for m in got)
    assert [{k: v for k, v in m.items() if k != "ev"} for m in got] == \
        [m for m in bare.messages if m["type"] == "ev"]


def test_nothing_is_sent_while_nothing_happens(tmp_path):
    scene = tmp_path / "still.toml"
    scene.write_text('[[bodies]]\nname = "player1"\nshape = "circle"\nposition = [0, 0]\nradius = 0.1\n'
                     '[[bodies]]\nname = "floor"\nkind = "static"\nshape = "segment"\n'
                     'points = [[-1, -1], [1, -1]]\n')
    running = start(scene)
    try:
        async def go():
            c = await Client.join(running.url)
            steps = running.call(lambda: running.server.rooms["main"].stats.steps)
            quiet = await c.receive(1.0)
            steps_after = running.call(lambda: running.server.rooms["main"].stats.steps)
            await c.send({"type": "key", "body": 0, "key": "down", "down": True})
            moved = await c.receive(1.0)
            return quiet, steps_after - steps, moved
        quiet, steps, moved = run(go())
        assert quiet == [] and steps == 0           # the loop slept: not even a wake-up
        # the ball heads for the floor at the input speed and bounces: two events, nothing else
        kinds = [e[0] for m in moved for e in m["ev"]]
        assert kinds[:2] == [5, 1] and len(moved) <= 3
    finally:
        running.stop()


def test_input_moves_only_your_body(arena):
    async def go():
        watcher = await Client.join(arena.url, play=False)
        a = await Client.join(arena.url)
        b = await Client.join(arena.url)
        c = await Client.join(arena.url)
        assert (watcher.world["you"], a.world["you"], b.world["you"], c.world["you"]) == ([], [4], [5], [])
        await b.send({"type": "key", "body": 4, "key": "left", "down": True})
        refused = await b.until(lambda m: m["type"] == "refused")
        await c.send({"type": "point", "body": 5, "x": 0, "y": 0})
        refused_c = await c.until(lambda m: m["type"] == "refused")
        await a.send({"type": "key", "body": 4, "key": "up", "down": True})
        moved = await c.until(lambda m: m["type"] == "ev" and [5, 4, -1] in m["ev"])
        return refused, refused_c, moved, arena.call(lambda: arena.server.rooms["main"].speed)
    refused, refused_c, moved, speed = run(go())
    assert "not yours" in refused["reason"] and refused["seq"] == 1
    assert "not yours" in refused_c["reason"]
    seg = next(s for s in wire.expanded(moved, (0, 0)) if s[0] == 4)   # (arena: no gravity)
    assert seg[4:6] == [0, speed]           # vx 0, vy = the input speed (no gravity here)


def test_late_joiner_sees_the_same_world(arena):
    async def go():
        a = await Client.join(arena.url)
        await a.send({"type": "key", "body": 4, "key": "right", "down": True})
        await a.receive(1.5)
        b = await Client.join(arena.url)
        await asyncio.gather(a.receive(0.5), b.receive(0.5))
        return a, b
    a, b = run(go())
    t = max(max(tt for _, tt in a.segs.values()), max(tt for _, tt in b.segs.values())) + 0.01
    for body in range(12):
        assert a.pose(body, t) == pytest.approx(b.pose(body, t), abs=1e-8)
    assert a.n == b.n


def test_rooms_are_independent_worlds_and_bounded():
    running = start(ARENA, max_rooms=2)
    try:
        async def go():
            a = await Client.join(running.url, room="one")
            b = await Client.join(running.url, room="two")
            assert a.world["you"] == b.world["you"] == [4]   # each room has its own players
            await a.send({"type": "key", "body": 4, "key": "right", "down": True})
            await a.until(lambda m: m["type"] == "ev" and [5, 4, -1] in m["ev"])
            got_b = await b.receive(0.3)
            third = await connect(running.url)
            await third.send(json.dumps({"type": "hello", "v": protocol.VERSION, "seq": 0, "room": "three"}))
            refusal = json.loads(await third.recv())
            return got_b, refusal
        got_b, refusal = run(go())
        assert not any([5, 4, -1] in m.get("ev", []) for m in got_b)
        assert refusal["type"] == "error" and "no more rooms" in refusal["reason"]
    finally:
        running.stop()


def test_page_and_files(arena):
    base = f"http://127.0.0.1:{arena.port}"
    with urllib.request.urlopen(base + "/") as r:
        assert r.status == 200 and b"<canvas" in r.read()
        assert "default-src 'self'" in r.headers["Content-Security-Policy"]
    with urllib.request.urlopen(base + "/client.js") as r:
        assert b"requestAnimationFrame" in r.read()
    for path in ("/../pyproject.toml", "/static/client.js", "/etc/passwd", "/%2e%2e/"):
        with pytest.raises(urllib.error.HTTPError) as e:
            urllib.request.urlopen(base + path)
        assert e.value.code == 404


def test_cross_origin_websocket_refused(arena):
    async def go():
        with pytest.raises(InvalidStatus) as e:
            await connect(arena.url, origin="http://evil.example")
        return e.value.response.status_code
    assert run(go()) == 403
