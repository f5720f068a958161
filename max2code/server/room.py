"""One room: an authoritative World, its clients, and the loop that sleeps between events.

The world runs at the server's clock (seconds since the room opened). The loop sleeps until
the engine's next queued event (World.next_time) or until input arrives, steps the world to
the clock, and sends one message for everything that happened in that step: the reported
events and the segments of the bodies whose motion changed (found by the core's per-body
change counters, and compared with what clients hold: a contact that changed nothing drawn
sends nothing). A step that changed nothing drawn (an internal cell crossing, a zero-impulse
contact) sends nothing, and with nothing queued the loop sleeps until input comes.

At most `rate` messages a second (60: a display's frame rate): a step within 1/rate of the
last message holds its changes back, and the next message, at the end of that interval,
carries them all, each body's latest segment only (what was superseded within the interval
is never drawn after the message arrives). An isolated event goes out at once; a burst (a
collapsing pile, a bullet bouncing 900 times a second) costs at most `rate` messages a
second. Input is never held back.
"""

from __future__ import annotations

import asyncio
import math
import time
from dataclasses import dataclass, field
from typing import Callable

from ..engine.scenefile import Scene, build_world
from ..engine.world import EngineError, Event, World
from . import ahead, protocol, reckon, wire


AUTO_PIXELS = 3200
RATE = 60.0          # most event messages per second (a display's frame rate); 0: no limit


@dataclass(eq=False)
class Client:
    """A joined connection: `send` takes a frame (the server's WebSocket, or a test's list):
    JSON text, or MessagePack bytes when its hello asked for them (`enc`)."""
    send: Callable[[str | bytes], None]
    name: str
    controls: tuple[int, ...] = ()
    keys: set[str] = field(default_factory=set)
    sent_bytes: int = 0
    events: bool = True      # false: ev messages reach it without "ev" (hello's events)
    enc: str = "json"        # hello's enc: "json" text frames or "msgpack" binary ones


@dataclass
class Stats:
    steps: int = 0
    messages: int = 0
    events: int = 0
    inputs: int = 0
    bytes_sent: int = 0
    shadows: int = 0        # copies of the world made to look ahead (ahead.Shadow)
    diverged: int = 0       # of which dropped because a tick's truth was not their record


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
                 tolerance: float | None = 0.0, world: World | None = None,
                 rate: float = RATE, lookahead: int = ahead.LOOKAHEAD) -> None:
        """`world`: a World made by the caller (a game with its callbacks) instead of the
        scene's; the scene then gives only the view (and the input speed). `rate`: most event
        messages a second (0: every step's changes at once). `lookahead`: solver ticks a copy
        of the world runs ahead to fit held bodies' segments to (ahead.py; 0: none, and never
        for a world with Python callbacks)."""
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
        self.zero = wire.Zero.of(self._view())
        # the world's gravity as sent: segments that fall with it leave it off (wire.split)
        self.fall = [protocol.number(v) for v in getattr(self.world, "gravity", (0.0, 0.0))]
        self.held: list[tuple[float, ...]] = [wire.motion(wire.segment(i, m, 0.0, self.zero), 0.0)
                                              for i, m in enumerate(motions)]
        self.due: dict[int, float] = {}
        # bodies the contact solver holds: clients get their chord (reckon.chord), and each is
        # checked again at `watch[i]`, when the truth would leave reckon.hop_bound of it
        self.step = float(getattr(self.world, "contact_step", 0.0))
        self.slop = self.world.contact_slop if self.step > 0 else 0.0
        self.modelled: set[int] = set()
        self.watch: dict[int, float] = {}
        # each held body's last tick poses (time, x, y, angle), for its quadratic (reckon.fitted)
        self.history: dict[int, list[tuple[float, float, float, float]]] = {}
        # a copy of the world run `lookahead` ticks ahead, made again after every edit (ahead.py)
        self.lookahead = lookahead if self.step > 0 and ahead.Shadow.possible(self.world) else 0
        self.shadow: ahead.Shadow | None = None
        self.copied = -math.inf     # the world's time when the last copy was made
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
        # the rate limit: when the last message went, and what waits for the next one
        self.gap = 1.0 / rate if rate > 0 else 0.0
        self.last_sent = -math.inf
        self.waiting_events: list[Event] = []
        self.waiting_removed: list[int] = []
        self.waiting_added: list[int] = []
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
        if self.failed is not None or t < self.world.time or (
                t == self.world.time and not self._waiting() and self.world.next_time() > t):
            return      # (an event queued at the world's own time is stepped: one at 0 in a
                        # world that starts in contact kept the loop waking for ever)
        try:
            events = self.world.step_to(t)
        except EngineError as exc:   # the world cannot go on: say so, keep serving the page
            self.failed = str(exc)
            self._broadcast({"type": "error", "reason": f"engine: {exc}"})
            return
        self.stats.steps += 1
        self.stats.events += len(events)
        self._look_ahead()
        self._send_changes(events, None)

    def _look_ahead(self) -> None:
        """Keep the world's copy `lookahead` ticks ahead of it (a new copy after an edit)."""
        if not self.lookahead:
            return
        if self.shadow is None or self.shadow.world.time < self.world.time:
            # (behind after a long sleep: a new copy costs less than the ticks it missed)
            if self.world.time < self.copied + self.lookahead * self.step:
                self.shadow = None      # at most one new copy a horizon (each steps one
                return                  # horizon at once): frequent input costs no more
            self.shadow = ahead.Shadow(self.world, self.step, self.lookahead)
            self.copied = self.world.time
            self.stats.shadows += 1
        try:
            self.shadow.run_to(self.world.time)
        except EngineError:     # its future fails (the room will say so when it gets there)
            self.shadow, self.lookahead = None, 0

    def _grow(self) -> None:
        """Per-body tables for bodies the world gained (a game adds them while it runs)."""
        for b in self.world.bodies[len(self.reach):]:
            self.reach.append(max(math.hypot(*v) + r for vs, r in b.shapes for v in vs))
            self.gravity.append(self.world.acceleration(b.id))   # (what it falls with when dynamic)
        motions, _ = self.world.motions()
        for i in range(len(self.held), len(motions)):
            self.held.append(wire.motion(wire.segment(i, motions[i], motions[i][0], self.zero),
                                         motions[i][0]))

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

    def _waiting(self) -> bool:
        """Anything owed to clients: a change whose wait or the rate's interval is not over."""
        return bool(self.due or self.waiting_removed or self.waiting_added)

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
            self.watch.pop(i, None)
            self.modelled.discard(i)
            self.history.pop(i, None)
        for i, d in list(self.watch.items()):   # a held body's chord about to leave its bound
            if d <= now:
                del self.watch[i]
                self.due[i] = now
        # with a tolerance, a change clients would not see yet waits (reckon.py); an input's
        # body is always sent, as is every body whose wait is over
        for i in changed:
            if (extra is None or extra[1] != i) and self.step > 0 and self.world.solving(i):
                self.modelled.add(i)   # (entering and leaving the solver bump the counter)
                poses = self.history.setdefault(i, [])
                if not poses or poses[-1][0] < motions[i][0]:
                    poses.append(tuple(motions[i][:4]))
                    del poses[:-reckon.HISTORY]
                    if self.shadow is not None and not self.shadow.agrees(i, motions[i]):
                        self.shadow = None      # it went another way: a new copy next step
                        self.stats.diverged += 1
                d = self._held_deadline(i, motions[i], now)
                if d is None:
                    self.due[i] = now
                    self.watch.pop(i, None)
                else:           # clients' chord is good until d: nothing owed
                    self.watch[i] = d
                    self.due.pop(i, None)
                continue
            self.modelled.discard(i)
            self.history.pop(i, None)
            self.watch.pop(i, None)
            self.due[i] = (reckon.deadline(self.held[i], motions[i], now, self.tolerance, self.reach[i])
                           if extra is None or extra[1] != i else now)
        for i in added:     # a new body's segment goes with it, whatever the tolerance
            self.due[i] = now
        self.waiting_events += [e for e in events if e.kind != "timer"]
        self.waiting_removed += removed
        self.waiting_added += added
        ready = any(d <= now for d in self.due.values())
        if not ready and not self.waiting_removed and not self.waiting_added and extra is None:
            self.waiting_events.clear()   # nothing drawn changed (or not yet: a tolerance's wait)
            return
        if extra is None and now < self.last_sent + self.gap:
            return          # the rate's interval is not over: next_wake() comes back then
        self._flush(motions, extra)

    def _flush(self, motions: list[tuple[float, ...]], extra: tuple[int, int, int] | None) -> None:
        """One message: every body whose change is due, the removals and additions since the
        last message, and the events of the bodies whose segments it carries."""
        now = self.world.time
        both = set(self.waiting_removed) & set(self.waiting_added)   # came and went: never sent
        removed = [i for i in self.waiting_removed if i not in both]
        added = [i for i in self.waiting_added if i not in both]
        drawn = self.waiting_events
        self.waiting_events, self.waiting_removed, self.waiting_added = [], [], []
        send = sorted(i for i, d in self.due.items() if d <= now)
        for i in send:
            del self.due[i]
        # the message's time: its latest change (or the input's time, now), so that a step
        # holding one instant sends no time per event; every segment is re-expressed from it
        # (t exact: rounded, it could fall before a removal the message carries)
        t = (max([motions[i][0] for i in send] + [e.time for e in drawn], default=now)
             if extra is None else now)
        segs = [wire.segment(i, self._held_motion(i, motions[i], t) if i in self.modelled
                             else motions[i], t, self.zero) for i in send]
        # a segment equal to what clients hold (re-expressed from t: a contact with no impulse,
        # a rest or wake that moved nothing) is not sent again, unless the body is new
        fresh = set(added)
        segs = [g for g in segs
                if g[0] in fresh or g != wire.segment(g[0], self.held[g[0]], t, self.zero)]
        sent = {g[0] for g in segs} | set(removed)
        if not segs and not removed and not added and extra is None:
            return
        ev = _events(drawn, sent, t)
        if extra is not None:
            ev.append(list(extra))
        for seg in segs:   # what clients now hold (the numbers as sent)
            self.held[seg[0]] = wire.motion(seg, t)
        for i in send:     # a held body's chord: checked again when it would leave its bound
            if i in self.modelled:
                d = self._held_deadline(i, motions[i], now)
                if d is None:   # (rounding only: a chord starts on the truth) the next message
                    self.due[i] = now
                else:
                    self.watch[i] = d
        self.seq += 1
        self.last_sent = now
        message = {"type": "ev", "n": self.seq, "t": t, "ev": ev, **self._segments(segs)}
        if removed:
            message["rm"] = removed
        if added:
            message["add"] = [wire.body(self.world, i) for i in added]
        self._broadcast(message)

    def _held_bound(self, truth: tuple[float, ...]) -> float:
        """How far what clients hold of a body the solver holds may be from its truth: twice
        reckon.hop_bound, or the room's tolerance if larger (one bound for choosing its segment
        and for when to send it again)."""
        return max(self.tolerance, 2 * reckon.hop_bound(truth, self.step, self.slop))

    def _held_motion(self, i: int, truth: tuple[float, ...], t: float) -> tuple[float, ...]:
        """What clients get from t for body i, which the solver holds: the cheapest in bytes a
        second, by their estimated lives, of its chord, the quadratic and the cubic fitted to
        its recent tick poses (reckon.fitted, when that history is smooth), each fit only when
        it stays within the bound until the solver's next tick (as a chord does) and counted
        at 1/reckon.CHEAPER of its bytes (their lives are estimated optimistically), each
        re-sent at most once a rate interval (a longer segment must last that much longer).
        With the world's copy ahead of it, by their lives against its record instead, the fits
        to the ticks ahead among them (_cheapest_ahead)."""
        chord = reckon.chord(truth, t, self.step)
        now = self.world.time
        eps = self._held_bound(truth)
        fit = reckon.fitted(self.history.get(i, []), truth, t, self.step, eps / 2, self.reach[i])
        flights = self.shadow.ahead(i, now) if self.shadow is not None else []
        if flights:
            return self._cheapest_ahead(i, truth, t, chord, fit, flights, eps)
        if fit is None:
            return chord
        best, cost = chord, self._bytes_a_second(i, chord, t, fit.chord_life)
        tick = reckon.next_tick(now, self.step)
        for m, life, cheaper in ((fit.motion, fit.life, reckon.CHEAPER),
                                 (fit.cubic, fit.cubic_life, reckon.CUBIC_CHEAPER)):
            if m is None or reckon.deadline(m, truth, now, eps, self.reach[i], soon=0.0) <= tick:
                continue
            c = self._bytes_a_second(i, m, t, life) / cheaper
            if c < cost:
                best, cost = m, c
        return best

    def _cheapest_ahead(self, i: int, truth: tuple[float, ...], t: float, chord: tuple[float, ...],
                        fit: reckon.Fit | None, flights: list[tuple[float, ...]],
                        eps: float) -> tuple[float, ...]:
        """_held_motion with the copy's record of the ticks ahead: the fewest bytes a second
        of the chord, the history's fits and the fits to the ticks ahead (ahead.forecast),
        each by how long it stays within the bound of the record (ahead.life), not by an
        estimate, and each only when it stays within the bound until the solver's next tick."""
        now, reach = self.world.time, self.reach[i]
        path = ahead.Ahead(truth, flights, t, eps / 2, reach, self.step)
        candidates = [(m, path.life(m)) for m in (chord, fit and fit.motion, fit and fit.cubic)
                      if m is not None]
        if candidates[0][1] < path.end:     # (a chord that lasts as far as is known is cheapest)
            candidates += path.forecast()
        tick = reckon.next_tick(now, self.step)
        best, cost = chord, math.inf
        for m, lasts in candidates:
            c = self._bytes_a_second(i, m, t, lasts)
            if c < cost and (m is chord or reckon.deadline(m, truth, now, eps, reach, soon=0.0) > tick):
                best, cost = m, c
        return best

    def _bytes_a_second(self, i: int, m: tuple[float, ...], t: float, life: float) -> float:
        """Body i's segment m (from t) in bytes over its estimated life (at least the rate's
        interval and a tick: it is re-sent at most that often)."""
        return len(protocol.encode(wire.segment(i, m, t, self.zero))) / max(life, self.gap, self.step)

    def _held_deadline(self, i: int, truth: tuple[float, ...], now: float) -> float | None:
        """For a body the contact solver holds: when the chord (quadratic, cubic) clients hold leaves
        the truth by more than reckon.hop_bound (or the room's tolerance, if larger), None when
        that comes before the solver's next tick (send it now: the change is real). Checked at every change
        of the truth (every tick), so clients stay within that bound at every instant."""
        eps = self._held_bound(truth)
        d = reckon.deadline(self.held[i], truth, now, eps, self.reach[i], soon=0.0)
        return None if d <= reckon.next_tick(now, self.step) else d

    def _segments(self, segs: list[list]) -> dict:
        """A message's `seg`, and its `fall` (segments accelerating at the room's g, sent
        without it: wire.split) when there are any."""
        explicit, fall = wire.split(segs, self.fall)
        return {"seg": explicit, "fall": fall} if fall else {"seg": explicit}

    def next_wake(self) -> float:
        """The next queued event, or the end of a change's wait (and of the rate's interval
        when a change waits for it), whichever is first."""
        owed = min(self.due.values(), default=-math.inf if self._waiting() else math.inf)
        queued = self.world.next_time()
        send = max(owed, self.last_sent + self.gap)
        if queued > send and queued - send <= 1e-6 * self.step:
            send = queued   # (the rate's k/60 falls some ulps before the solver's tick 4k:
                            # stepping it first sends the tick's motions, not the flight before)
        return min(queued, send, min(self.watch.values(), default=math.inf))

    def _broadcast(self, message: dict) -> None:
        """One message to every client; an ev message without its events to those that asked
        for none, in each client's encoding (encoded once for each kind of client there is)."""
        texts: dict[tuple[bool, str], str | bytes] = {}
        self.stats.messages += 1
        for c in list(self.clients):
            events = c.events or "ev" not in message
            text = texts.get((events, c.enc))
            if text is None:
                text = texts[events, c.enc] = protocol.encode(
                    message if events else {k: v for k, v in message.items() if k != "ev"}, c.enc)
            c.sent_bytes += len(text)
            self.stats.bytes_sent += len(text)
            c.send(text)

    # -- clients ----------------------------------------------------------------------------

    def join(self, send: Callable[[str | bytes], None], name: str, play: bool = True,
             events: bool = True, enc: str = "json") -> tuple[Client, str | bytes]:
        """A new client: the bodies it controls (the first free player body, if any) and the
        world message it starts from (every body's shape, style and segment now). `events`
        false: its ev messages come without their list of events; `enc`: its frames' encoding."""
        taken = {b for c in self.clients for b in c.controls}
        free = [b for b in self.players if b not in taken]
        client = Client(send, name, tuple(free[:1]) if play else (), events=events, enc=enc)
        self.advance(self.clock())
        if self._waiting():   # what the others are owed goes out first: a joiner starts level
            self._flush(self.world.motions()[0], None)
        t = self.world.time
        # a late joiner gets what the others hold (within the tolerance of the truth), so
        # that every client draws the same
        # (only the bodies alive now: a removed one is never drawn again)
        motions = self.held
        live = sorted(self.live)
        message = {"type": "world", "v": protocol.VERSION, "room": self.name, "n": self.seq,
                   "t": t, "you": list(client.controls), "view": self._view(),
                   "bodies": [wire.body(self.world, i) for i in live],
                   **self._segments([wire.segment(i, motions[i], t, self.zero) for i in live])}
        if self.fall != [0, 0]:
            message["g"] = self.fall
        if self.failed:
            message["failed"] = self.failed
        self.clients.append(client)
        return client, protocol.encode(message, enc)

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
        self.shadow = None      # (the copy did not get the input: a new one next step)
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
        self.shadow = None      # (the copy did not get the input: a new one next step)
        self._send_changes([], (protocol.EVENT_CODES["input"], body, -1))
        self._wake.set()
        return None


def _events(drawn: list[Event], sent: set[int], t: float) -> list[list]:
    """The events of one message: each (kind, a, b) once, at its latest time, in time order:
    [kind, a, b], then its time before t when that is not t, then how many times it happened
    since the last message when more than once (a ball rolling on a ramp touches it hundreds
    of times a second; a client draws none of them, and lists of them would cost more than the
    segments). An event of no body whose segment the message carries is left out (nobody sees
    it: a contact that changed nothing drawn)."""
    latest: dict[tuple[int, int, int], tuple[float, int]] = {}
    for e in drawn:
        if e.a in sent or e.b in sent:
            key = (protocol.EVENT_CODES[e.kind], e.a, e.b)
            latest[key] = (e.time, latest.get(key, (0.0, 0))[1] + 1)
    out = []
    for key, (time, count) in sorted(latest.items(), key=lambda kv: kv[1][0]):
        item = list(key)
        if time != t or count > 1:
            item.append(protocol.number(time - t))
        if count > 1:
            item.append(count)
        out.append(item)
    return out
