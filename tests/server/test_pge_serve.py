"""`max2code serve GAME.py`: PGE's own breakout (read from the shared corpus, never copied)
served in-process; its bricks' removals (its collision callbacks, run in the server's steps)
reach the client, whose bodies are the game's live objects after every message."""

from __future__ import annotations

import asyncio
import subprocess
import sys
from pathlib import Path

import pytest

from max2code.server.app import Options
import json

from max2code.engine.scenefile import Scene
from max2code.server.pgegame import UNIT_VIEW, GameWorld, load
from max2code.server.room import Room

from .client import Client
from .conftest import Running

BREAKOUT = Path("/work/shared/corpus/pge-python/examples/breakout-breakout.py")
corpus = pytest.mark.skipif(not BREAKOUT.is_file(), reason="no PGE corpus here")
SEQUENCE = """import pge

gold = pge.rgb(0.8, 0.6, 0.15)
floor = pge.box(0.0, 0.0, 1.0, 0.02, gold).fix()
ball = pge.circle(0.5, 0.8, 0.03, gold).mass(1.0)
pge.gravity()
pge.run(0.3)
late = pge.box(0.1, 0.5, 0.1, 0.1, gold).fix()
pge.run(0.3)
late.rm()
pge.run(0.2)
"""


def live(world: GameWorld) -> set[int]:
    return {b.id for b in world.bodies if b.alive}


def test_the_program_goes_on_after_each_run(tmp_path):
    """Code after a run() runs at that run's end, in the room's time: an object added at 0.3
    (a PGE rebuild) reaches the client as an addition, its removal at 0.6 as a removal, and the
    program's end stops the room with an error frame. No copy of it runs ahead."""
    from .test_membership import Clock

    game = tmp_path / "sequence.py"
    game.write_text(SEQUENCE)
    clock = Clock()
    room = Room("r", Scene(name="seq", bodies=(), view=UNIT_VIEW), (1,), clock=clock,
                world=GameWorld(load(str(game))))
    inbox: list[str] = []
    _, text = room.join(inbox.append, "a")
    c = Client.fed(text)
    assert [b["name"] for b in c.bodies.values()] == ["box-0", "circle-1"]
    added = removed = None
    for k in range(1, 101):
        clock.t = k * 0.01
        room.advance(clock.t)
        for m in map(json.loads, inbox):
            if m["type"] == "error":
                assert "ended" in m["reason"] and clock.t >= 0.8
                continue
            c.apply(m)
            if m.get("add"):
                added = (m["t"], [b["name"] for b in m["add"]])
            if m.get("rm"):
                removed = (m["t"], m["rm"])
        inbox.clear()
        if room.failed is None:
            assert set(c.bodies) == {b.id for b in room.world.bodies if b.alive}
            for i in c.bodies:   # every pose as the game has it (a rebuild re-sends them all)
                assert c.pose(i, clock.t)[:2] == pytest.approx(room.world.pose(i)[:2], abs=1e-9)
    assert added == (pytest.approx(0.3), ["box-2"]) and removed == (pytest.approx(0.6), [2])
    assert room.failed and "ended" in room.failed and set(c.bodies) == {0, 1}
    # a game's world is never copied to look ahead (ahead.py): its callbacks, and the program
    # itself, must run once
    assert room.lookahead == 0 and room.shadow is None


@corpus
def test_breakout_served_bricks_vanish_on_the_client():
    first = GameWorld(load(str(BREAKOUT)))
    bricks = {b.id for b in first.bodies if b.name.startswith("box-") and b.id >= 4}
    ball = [b.id for b in first.bodies if b.kind == "dynamic"]
    assert len(bricks) == 27 and len(ball) == 1
    options = Options(Scene(name="breakout", bodies=(), view=UNIT_VIEW), tuple(ball), tolerance=0.0,
                      world=lambda: GameWorld(load(str(BREAKOUT))))
    running = Running(options)
    try:
        async def go():
            c = await Client.join(running.url)
            await c.receive(0.3)
            # a key for a body that is not ours is refused; ours reaches the game's handler
            await c.send({"type": "key", "body": 0, "key": "left", "down": True})
            await c.send({"type": "key", "body": ball[0], "key": "left", "down": True})
            await c.receive(2.7)
            return c
        c = asyncio.run(go())
    finally:
        running.stop()
    assert c.world["you"] == ball and len(c.world["bodies"]) == 34
    assert any(m["type"] == "refused" for m in c.messages)
    assert any(e[0] == 5 for m in c.messages if m["type"] == "ev" for e in m["ev"])
    removed = [i for m in c.messages if m["type"] == "ev" for i in m.get("rm", [])]
    assert len(removed) >= 5 and set(removed) <= bricks and len(set(removed)) == len(removed)
    # replayed against the same game stepped on its own: the client's bodies are its live
    # objects at every message's time
    bodies = {b["id"] for b in c.world["bodies"]}
    reference = GameWorld(load(str(BREAKOUT)))
    for m in c.messages:
        if m["type"] != "ev":
            continue
        bodies = (bodies - set(m.get("rm", []))) | {b["id"] for b in m.get("add", [])}
        reference.step_to(m["t"])
        assert bodies == live(reference), m["t"]
    assert set(c.bodies) == bodies


def test_serve_cli_refuses_a_broken_game(tmp_path):
    game = tmp_path / "broken.py"
    game.write_text("import pge\n\npge.box(0, 0, 1, 1)\npge.run()\n")
    r = subprocess.run([sys.executable, "-m", "max2code", "serve", str(game), "--port", "0"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 1 and f"{game}:3:" in r.stderr and "error:" in r.stderr, r.stderr


@corpus
def test_rooms_of_one_game_are_independent():
    """Each room runs the program afresh, and `pge` calls inside one room's step (breakout's
    bricks' `rm` when hit, and its end: `pge.at_time(4.0, finish_game)` after the last brick, or
    the engine's named error when the ball's speed runs away first, which is chaotic:
    tests/pge/test_corpus.py) reach that room's game only."""
    from max2code.engine.world import EngineError

    a, b = GameWorld(load(str(BREAKOUT))), GameWorld(load(str(BREAKOUT)))
    alive_a, ended = {}, None
    for k in range(1, 41):
        try:
            a.step_to(k * 0.25)
        except EngineError as exc:
            ended = (k * 0.25, str(exc))
            break
        alive_a[k * 0.25] = live(a)
    assert ended
    if "ended (exit 0)" in ended[1]:   # the win: every brick gone from a
        assert not any(b_.name.startswith("box-") and b_.id >= 4 for b_ in a.bodies if b_.alive)
    else:                              # the runaway, named
        assert "stuck" in ended[1] and "too fast for double precision" in ended[1], ended[1]
    assert len(alive_a[0.25]) > len(alive_a[2.0])   # a lost bricks before b was ever stepped
    for t in (0.25, 0.5, 1.0, 2.0):   # b, stepped only now, is where a was at those times
        b.step_to(t)
        assert live(b) == alive_a[t]
    assert b.over is None and b.next_time() < 3.0
