"""One room: an authoritative World, its clients, and the loop that sleeps between events.

The world runs at the server's clock (seconds since the room opened). The loop sleeps until
the engine's next queued event (World.next_time) or until input arrives, steps the world to
the clock, and sends one message for everything that happened in that step: the reported
events and the segments of the bodies whose motion changed (found by the core's per-body
change counters). A step that changed nothing drawn (an internal cell crossing) sends
nothing, and with nothing queued the loop sleeps until input comes.
"""

from __future__ import annotations

import asyncio
import math
import time
from dataclasses import dataclass, field
from typing import Callable

from ..engine.scenefile import Scene, build_world
from ..engine.world import EngineError, Event, World
from . import protocol, reckon, wire


AUTO_PIXELS = 3200


@dataclass(eq=False)
class Client:
    """A joined connection: `send` takes a text frame (the server's WebSocket, or a test's list)."""
    send: Callable[[str], None]
    name: str
    controls: tuple[int, ...] = ()
    keys: set[str] = field(default_factory=set)
    sent_bytes: int = 0


@dataclass
class Stats:
    steps: int = 0
    messages: int = 0
    events: int = 0
    inputs: int = 0
    bytes_sent: int = 0


def _speed(scene: Scene) -> float:
    """Input speed: a quarter of the scene's width per second (view, else the bodies' extent)."""
    if scene.view:
        return (scene.view[2] - scene.view[0]) / 4
    xs = [b.position[0] + v[0] for b in scene.bodies for v in b.vertices]
    return max((max(xs) - min(xs)) / 4, 1.0) if xs else 1.0


class Room:
    """An independent world shared by its clients. `clock` gives the room's time (seconds)."""

    def __init__(self, name: str, scene: Scene, players: tuple[int, ...],
                 clock: Callable[[], float] | None = None, speed: float | None = None,
                 tolerance: float | None = 0.0, world: World | None = None) -> None:
        """`world`: a World made by the caller (a game with its callbacks) instead of the
        scene's; the scene then gives only the view (and the input speed)."""
        self.name = name
        self.scene = scene
        self.world = world if world is not None else build_world(scene)
        self.players = players
        self.speed = speed if speed is not None else _speed(scene)
        start = time.monotonic()
        self.clock = clock or (lambda: time.monotonic() - start)
        self.clients: list[Client] = []
        motions, self.counters = self.world.motions()
        # what clients hold of each body (the tolerance compares changes with it), the time
        # by which a held segment must be replaced, and how far each body reaches from its
        # reference point (rotation moves points that far out by angle x reach)
        self.tolerance = 0.0
        self.held: list[tuple[float, ...]] = [wire.motion(wire.segment(i, m, 0.0), 0.0)
                                              for i, m in enumerate(motions)]
        self.due: dict[int, float] = {}
        self.reach: list[float] = []
        self.gravity: list[tuple[float, float]] = []
        self._grow()
        # the bodies clients know of: every id below `known`, and of those the ones alive
        self.known = len(self.world.bodies)
        self.live = {i for i, b in enumerate(self.world.bodies) if b.alive}
        if tolerance is None:   # a quarter of a pixel of the page's 800-pixel-wide canvas
            view = self._view()
            tolerance = (view[2] - view[0]) / AUTO_PIXELS
        self.tolerance = float(tolerance)
        self.seq = 0
        self.stats = Stats()
        self.failed: str | None = None
        self._wake = asyncio.Event()
        self._task: asyncio.Task | None = None

    # -- the loop ---------------------------------------------------------------------------

    def start(self) -> None:
        self._task = asyncio.get_running_loop().create_task(self._run())

    async def stop(self) -> None:
        if self._task:
            self._task.cancel()
            try:
                await self._task
            except asyncio.CancelledError:
                pass

    async def _run(self) -> None:
        while self.failed is None:
            delay = self.next_wake() - self.clock()
            self._wake.clear()
            if delay > 0:
                try:
                    await asyncio.wait_for(self._wake.wait(), None if math.isinf(delay) else delay)
                except asyncio.TimeoutError:
                    pass
            else:
                await asyncio.sleep(0)   # let connections run between busy steps
            self.advance(self.clock())

    def advance(self, t: float) -> None:
        """Step the world to t and send what changed (nothing when nothing drawn changed)."""
        if self.failed is not None or t < self.world.time or (t == self.world.time and not self.due):
            return
        try:
            events = self.world.step_to(t)
        except EngineError as exc:   # the world cannot go on: say so, keep serving the page
            self.failed = str(exc)
            self._broadcast({"type": "error", "reason": f"engine: {exc}"})
            return
        self.stats.steps += 1
        self.stats.events += len(events)
        self._send_changes(events, None)

    def _grow(self) -> None:
        """Per-body tables for bodies the world gained (a game adds them while it runs)."""
        for b in self.world.bodies[len(self.reach):]:
            self.reach.append(max(math.hypot(*v) for v in b.vertices) + b.radius)
            self.gravity.append(self.world.acceleration(b.id))   # (what it falls with when dynamic)
        motions, _ = self.world.motions()
        for i in range(len(self.held), len(motions)):
            self.held.append(wire.motion(wire.segment(i, motions[i], motions[i][0]), motions[i][0]))

    def _membership(self) -> tuple[list[int], list[int]]:
        """Bodies removed since the last message (were alive, are not) and bodies added (ids
        past the last known; one added and removed within a step is never sent)."""
        bodies = self.world.bodies
        removed = sorted(i for i in self.live if not bodies[i].alive)
        added = [i for i in range(self.known, len(bodies)) if bodies[i].alive]
        self.known = len(bodies)
        self.live.difference_update(removed)
        self.live.update(added)
        if added or len(self.reach) < len(bodies):
            self._grow()
        return removed, added

    def _send_changes(self, events: list[Event], extra: tuple[int, int, int] | None) -> None:
        motions, counters = self.world.motions()
        removed, added = self._membership()
        new = set(added)
        changed = [i for i, (c, old) in enumerate(zip(counters, self.counters))
                   if c != old and i in self.live and i not in new]
        self.counters = counters
        now = self.world.time
        for i in removed:   # (its wait, if any, is over: clients drop it)
            self.due.pop(i, None)
        drawn = [e for e in events if e.kind != "timer"]
        # with a tolerance, a change clients would not see yet waits (reckon.py); an input's
        # body is always sent, as is every body whose wait is over
        for i in changed:
            self.due[i] = (reckon.deadline(self.held[i], motions[i], now, self.tolerance, self.reach[i])
                           if extra is None or extra[1] != i else now)
        for i in added:     # a new body's segment goes with it, whatever the tolerance
            self.due[i] = now
        send = sorted(i for i, d in self.due.items() if d <= now)
        if not send and not removed and extra is None and (self.tolerance > 0 or not drawn):
            return
        for i in send:
            del self.due[i]
        # the message's time: its latest event (or the input's, or now for a wait that ended),
        # so that a step holding one instant sends no time per event; every segment is
        # re-expressed from it
        times = [e.time for e in drawn] + [motions[i][0] for i in send]
        t = max(times) if times and extra is None else now
        sent = set(send) | set(removed)
        ev = []
        for e in drawn:   # [kind, a, b], and the time before t when the step held several
            if self.tolerance > 0 and e.a not in sent and e.b not in sent:
                continue  # (an event nobody sees)
            item = [protocol.EVENT_CODES[e.kind], e.a, e.b]
            ev.append(item if e.time == t else item + [protocol.number(e.time - t)])
        if extra is not None:
            ev.append(list(extra))
        segs = [wire.segment(i, motions[i], t) for i in send]
        for seg in segs:   # what clients now hold (the numbers as sent)
            self.held[seg[0]] = wire.motion(seg, t)
        self.seq += 1
        message = {"type": "ev", "n": self.seq, "t": t, "ev": ev, "seg": segs}
        if removed:
            message["rm"] = removed
        if added:
            message["add"] = [wire.body(self.world, i) for i in added]
        self._broadcast(message)

    def next_wake(self) -> float:
        """The next queued event, or the end of a change's wait, whichever is first."""
        return min([self.world.next_time()] + list(self.due.values()))

    def _broadcast(self, message: dict) -> None:
        text = protocol.encode(message)
        self.stats.messages += 1
        for c in list(self.clients):
            c.sent_bytes += len(text)
            self.stats.bytes_sent += len(text)
            c.send(text)

    # -- clients ----------------------------------------------------------------------------

    def join(self, send: Callable[[str], None], name: str, play: bool = True) -> tuple[Client, str]:
        """A new client: the bodies it controls (the first free player body, if any) and the
        world message it starts from (every body's shape, style and segment now)."""
        taken = {b for c in self.clients for b in c.controls}
        free = [b for b in self.players if b not in taken]
        client = Client(send, name, tuple(free[:1]) if play else ())
        self.advance(self.clock())
        t = self.world.time
        # a late joiner gets what the others hold (within the tolerance of the truth), so
        # that every client draws the same
        # (only the bodies alive now: a removed one is never drawn again)
        motions = self.held
        live = sorted(self.live)
        message = {"type": "world", "v": protocol.VERSION, "room": self.name, "n": self.seq,
                   "t": t, "you": list(client.controls), "view": self._view(),
                   "bodies": [wire.body(self.world, i) for i in live],
                   "seg": [wire.segment(i, motions[i], t) for i in live]}
        if self.failed:
            message["failed"] = self.failed
        self.clients.append(client)
        return client, protocol.encode(message)

    def leave(self, client: Client) -> None:
        if client in self.clients:
            self.clients.remove(client)

    def _view(self) -> list[float]:
        """The scene's view, else one fit to every body now (max2code.render.fit)."""
        if self.scene.view:
            return list(self.scene.view)
        from ..engine.frames import frame, render_bodies
        from ..render.fit import fit_view

        v = fit_view(render_bodies(self.world), [frame(self.world, self.world.time)])
        return [protocol.number(x) for x in (v.xmin, v.ymin, v.xmax, v.ymax)]

    # -- input ------------------------------------------------------------------------------

    def key(self, client: Client, body: int, key: str, down: bool) -> str | None:
        """A key pressed or released for a body the client controls; None, or why refused."""
        if body not in client.controls:
            return f"body {body} is not yours (you control {list(client.controls)})"
        held = client.keys
        was = set(held)
        (held.add if down else held.discard)(key)
        if held == was:
            return None
        self.advance(self.clock())
        to_game = getattr(self.world, "input", None)
        if to_game is not None:   # a PGE game: the key goes to its handlers (pgegame.py)
            return self._game_input(body, lambda: to_game("KEYDOWN" if down else "KEYUP", key))
        vx, vy, w = self.world.velocity(body)
        dx = ("right" in held) - ("left" in held)
        dy = ("up" in held) - ("down" in held)
        if self.gravity[body] != (0.0, 0.0):   # a platformer: left/right walk, up jumps
            vx = dx * self.speed
            if key == "up" and down:
                vy = self.speed
        else:
            norm = math.hypot(dx, dy) or 1.0
            vx, vy = dx * self.speed / norm, dy * self.speed / norm
        return self._input(body, vx, vy, w)

    def point(self, client: Client, body: int, x: float, y: float) -> str | None:
        """A pointer press: the body heads for (x, y) at the input speed."""
        if body not in client.controls:
            return f"body {body} is not yours (you control {list(client.controls)})"
        if hasattr(self.world, "input"):
            return "a PGE game takes keys only (pointer input is not passed to it yet)"
        self.advance(self.clock())
        px, py, _ = self.world.pose(body)
        _, _, w = self.world.velocity(body)
        d = math.hypot(x - px, y - py)
        if d == 0:
            return None
        return self._input(body, (x - px) / d * self.speed, (y - py) / d * self.speed, w)

    def _game_input(self, body: int, deliver: Callable[[], None]) -> str | None:
        if self.failed:
            return "the world stopped: " + self.failed
        try:
            deliver()
        except EngineError as exc:
            return str(exc)
        self.stats.inputs += 1
        self._send_changes([], (protocol.EVENT_CODES["input"], body, -1))
        self._wake.set()
        return None

    def _input(self, body: int, vx: float, vy: float, w: float) -> str | None:
        if self.failed:
            return "the world stopped: " + self.failed
        try:
            self.world.set_velocity(body, (vx, vy), w)
        except EngineError as exc:
            return str(exc)
        self.stats.inputs += 1
        self._send_changes([], (protocol.EVENT_CODES["input"], body, -1))
        self._wake.set()
        return None
