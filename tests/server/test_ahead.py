"""A held body's segment fitted to the ticks ahead (max2code/server/ahead.py; docs/server.md,
"A held body's segment from the ticks ahead"): a copy of the room's world runs ahead of it,
and the room fits a held body's segment to that copy's record of the next ticks.

Every pose a client draws is checked against an oracle: a second World built the same way in
a run of its own (stepped to each instant checked, the inputs given at the same times), never
the room's world or its copy. The bound is computed from its documented terms."""

from __future__ import annotations

import json
import math
import random

from max2code.engine.scenefile import Scene
from max2code.engine.world import World
from max2code.server import ahead
from max2code.server.room import Room

from .client import Client
from .test_held import G, H, VIEW, tipping


def run(make, until: float, inputs=(), lookahead: int = ahead.LOOKAHEAD, seed: int = 1,
        corrupt: float | None = None):
    """Serve make()'s world exactly (every change at once, rate 0) with `inputs` ((time,
    body, key) presses of the body's own player) and check every held pose the client draws,
    at every wake of the room and at two random instants before the next, against an oracle
    World of make()'s own with the same inputs: within slop + |g| h^2 / 8 along x and y and
    through rotation at the body's reach, every other pose within 1e-9 of the view. `corrupt`:
    at that time give the room's copy a velocity the world never gets (a forecast gone wrong).
    Returns (the times of the held segments each body got, the room)."""
    w, reach = make()
    oracle, _ = make()
    players = tuple(sorted({b for _, b, _, _ in inputs}))
    clock = [0.0]
    room = Room("ahead", Scene(name="ahead", bodies=(), view=VIEW), players,
                clock=lambda: clock[0], tolerance=0.0, world=w, rate=0.0, lookahead=lookahead,
                speed=0.5)
    inbox: list[str] = []
    me, text = room.join(inbox.append, "a", events=False)
    c = Client.fed(text)
    rng = random.Random(seed)
    bound = w.contact_slop + G * H * H / 8
    exact = 1e-9 * (VIEW[3] - VIEW[1])
    pending = sorted(inputs)
    held: dict[int, list[float]] = {i: [] for i in reach}
    corrupted = False

    def check(s: float) -> None:
        oracle.step_to(s)
        for i in reach:
            (x, y, a), (X, Y, A) = c.pose(i, s), oracle.pose(i, s)
            turn = a - A
            turn -= 2 * math.pi * round(turn / (2 * math.pi))
            limit = bound * (1 + 1e-9) if oracle.solving(i) else exact
            assert abs(x - X) <= limit and abs(y - Y) <= limit and abs(turn) * reach[i] <= limit + 1e-15, \
                (i, s, oracle.solving(i), c.segs[i], x - X, y - Y, turn * reach[i], limit)

    def deliver() -> None:
        for m in map(json.loads, inbox):
            c.apply(m)
            for seg in m.get("seg", []) + m.get("fall", []):
                if w.solving(seg[0]):
                    held[seg[0]].append(m["t"])
        inbox.clear()

    while True:
        t = min(room.next_wake(), pending[0][0] if pending else math.inf)
        if t > until:
            break
        clock[0] = t
        if pending and pending[0][0] == t:
            _, body, key, down = pending.pop(0)
            assert room.key(me, body, key, down) is None
            oracle.step_to(t)       # (the room's input: walk at its speed, keep vy and the spin)
            _, vy, spin = oracle.velocity(body)
            oracle.set_velocity(body, ((0.5 if key == "right" else -0.5) if down else 0.0, vy), spin)
        else:
            room.advance(t)
        if corrupt is not None and not corrupted and t >= corrupt and room.shadow is not None:
            for i in reach:
                vx, vy, spin = room.shadow.world.velocity(i)
                room.shadow.world.set_velocity(i, (vx + 0.2, vy), spin)
            corrupted = True
        deliver()
        after = min(room.next_wake(), pending[0][0] if pending else until, until)
        for s in sorted((t, t + rng.random() * (after - t), t + rng.random() * (after - t))):
            check(s)
    return held, room


def lives(times: list[float]) -> list[float]:
    """Solver ticks between successive held segments of a body."""
    return [(b - a) / H for a, b in zip(times, times[1:])]


def test_a_tipping_box_segments_last_longer_than_its_history_allows():
    """The tipping-box scene's box (0.6 rad, half sides 0.25 by 0.2) tips over its corner for
    some 100 ticks: from its history a cubic lasted at most 12 ticks (its jerk changes within
    a dozen), and the box got 27 held segments in 1.5 s; fitted to the ticks ahead some last
    30 (bench/held_life.py's oracle). All within the bound of the oracle's poses."""
    held, room = run(lambda: tipping("box", 0.6, 0.25, 0.5), 1.5)
    box = next(iter(held))
    assert max(lives(held[box])) >= 20, lives(held[box])
    assert len(held[box]) <= 10, lives(held[box])
    assert room.stats.shadows == 1 and room.stats.diverged == 0


def test_an_input_mid_forecast_stays_within_the_bound():
    """The box tipping, its player pressing right at 0.2 s and letting go at 0.3 s (walk at
    0.5 m/s, then stop: set_velocity, its spin kept): the copy ahead had not got either; the room makes a new one after each,
    and every pose drawn stays within the bound of an oracle given the same inputs."""
    make = lambda: tipping("box", 0.6, 0.25, 0.5)   # noqa: E731
    box = next(iter(make()[1]))
    held, room = run(make, 1.0, inputs=((0.2, box, "right", True), (0.3, box, "right", False)))
    assert room.stats.inputs == 2
    assert room.stats.shadows == 3      # the first copy, and one after each input
    assert held[box]


def test_a_wrong_forecast_costs_bytes_not_exactness():
    """The room's copy is given a velocity the world never gets, mid-tip: its record of the
    ticks ahead is wrong, yet every pose drawn stays within the bound of the oracle (the room
    checks what clients hold against the truth at every tick), and the room notices the copy
    went another way (a tick's truth is not its record) and makes a new one."""
    held, room = run(lambda: tipping("box", 0.6, 0.25, 0.5), 1.0, corrupt=0.15)
    assert room.stats.diverged >= 1 and room.stats.shadows >= 2
    assert held


def test_worlds_with_python_callbacks_are_never_copied():
    """A world whose stepping runs its owner's Python code (a collision callback, a timer's:
    PGE's games) is served without a copy ahead: each callback runs once per event, as in a
    run of the world alone."""
    def make():
        w, reach = tipping("box", 0.6, 0.25, 0.5)
        calls: list[float] = []
        w.on_collision(lambda world, ev: calls.append(ev.time))
        return w, reach, calls

    w, _, calls = make()
    clock = [0.0]
    room = Room("cb", Scene(name="cb", bodies=(), view=VIEW), (), clock=lambda: clock[0],
                tolerance=0.0, world=w)
    while (t := room.next_wake()) <= 1.0:
        clock[0] = t
        room.advance(t)
    alone, _, alone_calls = make()
    alone.step_to(w.time)
    assert room.lookahead == 0 and room.shadow is None
    assert calls == alone_calls and calls


def test_a_plain_scene_world_is_copied():
    """(The converse: a world without callbacks gets its copy, with the solver on.)"""
    w, _ = tipping("box", 0.6, 0.25, 0.5)
    room = Room("plain", Scene(name="plain", bodies=(), view=VIEW), (), clock=lambda: 0.0,
                tolerance=0.0, world=w)
    assert room.lookahead == ahead.LOOKAHEAD
    assert not World(gravity=(0.0, -G)).has_callbacks()


def test_frequent_input_makes_at_most_one_copy_a_horizon():
    """The player pressing and releasing a key every 50 ms (20 inputs a second): each input
    leaves the copy behind, but a new one (which steps a whole horizon at once) is made at
    most once a horizon (48 ticks, 0.2 s), so the copies' work stays within about the
    world's own; 20 copies in 1 s without that bound. Every pose within the bound of the
    oracle given the same inputs."""
    make = lambda: tipping("box", 0.6, 0.25, 0.5)   # noqa: E731
    box = next(iter(make()[1]))
    presses = tuple((0.05 * k, box, "right", k % 2 == 1) for k in range(1, 20))
    _, room = run(make, 1.0, inputs=presses)
    assert room.stats.inputs == len(presses)
    assert room.stats.shadows <= 1 + 1.0 / (ahead.LOOKAHEAD * H) + 1, room.stats


def test_serve_lookahead_reaches_each_room():
    """`max2code serve --lookahead TICKS`: each room's copy runs that far ahead (0: none)."""
    import asyncio
    from pathlib import Path

    from max2code.commands.serve import _options, _parser
    from max2code.server.app import Server

    arena = str(Path(__file__).resolve().parents[2] / "examples" / "scenes" / "arena.toml")

    async def rooms() -> list[int]:
        out = []
        for ticks in ([], ["--lookahead", "0"], ["--lookahead", "12"]):
            server = Server(_options(_parser().parse_args([arena, *ticks]))[0])
            out.append(server.room("main").lookahead)
            await server.close()
        return out

    assert asyncio.run(rooms()) == [ahead.LOOKAHEAD, 0, 12]
