"""A PGE game's state and its event loop: frames, timers, input and collisions in time order.

Time is the physics' (PGE's `run(t)` and `at_time` count simulated seconds; `at_time`'s delay is
divided by `slow_down` as PGE does). The loop takes the earliest of: the next frame (every 1/fps
of simulated time), the next timer, the next scripted input, the end of `run`; the physics
processes every collision before it, at its exact time, calling the objects' callbacks there.
Live, frames are shown `slow_down` times slower than simulated time and pygame's events are
handled at the time of the frame after which they arrived (and logged with it, so a replay of
the log gives the same game).
"""

from __future__ import annotations

import heapq
import inspect
import math
import time as wallclock
from dataclasses import dataclass, field
from typing import Callable

from ..render.items import Frame, Item, body_item
from .objects import Colour, Decoration, Event, Shape
from .physics import Physics, PgeError

BATCH_RUN = 30.0  # PGE's run() without a time in batch mode simulates 30 s


class GameOver(BaseException):
    """The game ended (the run reached --until, or the window was closed with no QUIT handler):
    BaseException, so that a game's `except Exception` cannot stop it."""

    def __init__(self, code: int = 0) -> None:
        super().__init__(code)
        self.code = code


@dataclass(order=True)
class Timed:
    """A queued input or timer: ordered by time, then by the order they were made."""
    time: float
    seq: int
    kind: str = field(compare=False)
    payload: object = field(compare=False)


@dataclass
class Options:
    """How the command runs the game (max2code.pge.command)."""
    headless: bool = True
    until: float | None = None
    fps: float | None = None      # frames per simulated second (default: the game's pge.fps)
    record: bool = False          # keep every frame (for --gif/--mp4/--png-dir)
    inputs: list = field(default_factory=list)   # (time, type name, attributes) of scripted input
    # `max2code serve GAME.py`: run(t) calls serve(game, end) instead of looping, which returns
    # once the server has run the game to `end` (max2code.server.pgegame)
    serve: Callable[["Game", float], None] | None = None


def call_back(p: Callable, *args) -> None:
    """PGE calls timer functions with (event, None); games declare fewer parameters too
    (snooker's `finish_game(e=None)`), so pass as many as the function takes."""
    try:
        sig = inspect.signature(p)
    except (TypeError, ValueError):
        p(*args)
        return
    for n in range(len(args), -1, -1):
        try:
            sig.bind(*args[:n])
        except TypeError:
            continue
        p(*args[:n])
        return
    p(*args)


class Game:
    def __init__(self, options: Options | None = None) -> None:
        self.options = options or Options()
        self.physics = Physics()
        self.physics.on_contact = self._contact
        self.physics.springs.on_event = self._spring_event
        self.tint: dict[str, Colour] = {}
        self.shapes: list[Shape] = []
        self.decorations: list[Decoration] = []
        self.handlers: dict[int, Callable] = {}
        self.queue: list[Timed] = []
        self.seq = 0
        self.cancelled: set[int] = set()
        self.resolution = 0
        self.game_fps = 100.0
        self.slow = 1.0
        self.draw_actual = False
        self.collision_colour = Colour(1.0, 1.0, 1.0)
        self.flash: set[str] = set()
        self.frames: list[Frame] = []
        self.frame_no = 0
        self.last_frame = -math.inf
        self.log: list[dict] = []
        self.window = None
        self.wall0: float | None = None
        self._inputs_queued = False
        self.handed_off = False

    # -- time -------------------------------------------------------------------------------

    @property
    def now(self) -> float:
        return self.physics.now

    @property
    def fps(self) -> float:
        return self.options.fps or self.game_fps

    def at_time(self, delay: float, p: Callable) -> int:
        self.seq += 1
        heapq.heappush(self.queue, Timed(self.now + float(delay) / self.slow, self.seq, "timer", p))
        return self.seq

    def at_cancel(self, i: int) -> None:
        if i in self.cancelled or not any(q.kind == "timer" and q.seq == i for q in self.queue):
            raise PgeError(f"at_cancel: no pending timer {i}")
        self.cancelled.add(i)

    def _queue_inputs(self) -> None:
        if self._inputs_queued:
            return
        self._inputs_queued = True
        for t, kind, attrs in self.options.inputs:
            self.seq += 1
            heapq.heappush(self.queue, Timed(float(t), self.seq, "input", (kind, attrs)))

    def run(self, t: float = -1) -> None:
        """Simulate t seconds (PGE: t < 0 runs on, 30 s in batch mode), drawing every frame."""
        self._queue_inputs()
        if self.options.serve is not None:   # the server's room steps it (server/pgegame.py)
            self.physics.advance(self.now)
            self.handed_off = True
            self.options.serve(self, self.now + (float(t) if t >= 0 else math.inf))
            return
        t = float(t)
        end = self.now + (t if t >= 0 else (math.inf if not self.options.headless else BATCH_RUN))
        until = self.options.until if self.options.until is not None else math.inf
        if self.frame_no == 0:
            self._frame()
        while True:
            t_frame = self.frame_no / self.fps
            t_queue = self.queue[0].time if self.queue else math.inf
            nxt = min(t_frame, t_queue, end, until)
            if nxt == math.inf:
                raise GameOver(0)
            self.physics.advance(max(nxt, self.now))
            if nxt == t_frame:
                self._frame()
            elif nxt == t_queue:
                self.fire_next()
            elif nxt == end:
                return
            else:
                if self.last_frame < until:
                    self._frame()
                raise GameOver(0)

    def fire_next(self) -> None:
        """Fire the earliest queued timer or input event (the game's loop, and the server's)."""
        q = heapq.heappop(self.queue)
        if q.kind == "timer":
            if q.seq in self.cancelled:
                self.cancelled.discard(q.seq)
                return
            self.log.append({"t": self.now, "kind": "timer", "id": q.seq})
            ev = Event("timer", self.now, timer_id=q.seq)
            call_back(q.payload, ev, None)
        else:
            kind, attrs = q.payload
            self.input(kind, attrs)

    def input(self, kind: str, attrs: dict) -> None:
        """An input event now: to its registered handler (as a pygame event), and to the log."""
        import pygame

        code = getattr(pygame, kind)
        logged = dict(attrs)
        if "key" in logged:
            logged["key"] = key_name(logged["key"])
        self.log.append({"t": self.now, "kind": "input", "type": kind, **logged})
        handler = self.handlers.get(code)
        if handler is not None:
            handler(pygame.event.Event(code, {k: tuple(v) if isinstance(v, list) else v
                                              for k, v in attrs.items()}))
        elif kind == "QUIT":
            raise GameOver(0)

    # -- collisions -------------------------------------------------------------------------

    def _contact(self, a: Shape, b: Shape, ev, t: float) -> None:
        self.log.append({"t": t, "kind": "collision", "a": a.name, "b": b.name,
                         "point": list(ev.point), "speed": ev.speed})
        if self.draw_actual:
            self.flash.update((a.name, b.name))
        between = [a, b]
        e = Event("collision", t, between=between, point=ev.point)
        for ob in between:
            ob.collided(between, e)

    # -- springs ----------------------------------------------------------------------------

    def add_spring(self, a, b, k, d, l):
        from .springs import make

        return make(self.physics, a, b, k, d, l, f"spring-{len(self.physics.springs.springs)}")

    def _spring_event(self, s, what: str, t: float, length: float | None, p) -> None:
        """A spring reached its rest length (mid), a turning point (end) or a `when` length,
        at time t (the physics' time now)."""
        self.log.append({"t": t, "kind": "spring", "spring": s.name, "what": what,
                         "length": length})
        colour = {"mid": s.mid_colour, "end": s.end_colour}.get(what)
        if colour is not None:
            for ob in (s.a, s.b):
                self.tint[ob.name] = colour
        if p is not None:
            call_back(p, s, Event("spring", t))

    def add(self, shape: Shape) -> Shape:
        self.shapes.append(shape)
        self.physics.add(shape)
        return shape

    def remove(self, shape: Shape) -> None:
        self.physics.remove(shape)
        self.log.append({"t": self.now, "kind": "rm", "object": shape.name})

    # -- frames -----------------------------------------------------------------------------

    def _frame(self) -> None:
        frame = self.snapshot()
        self.frame_no += 1
        self.last_frame = frame.time
        if self.options.record:
            self.frames.append(frame)
        if not self.options.headless:
            self._show(frame)

    def snapshot(self) -> Frame:
        """Every visible thing now: decorations below level 0, the shapes, those above."""
        items: list[Item] = []
        behind = sorted((d for d in self.decorations if d.level < 0), key=lambda d: d.level)
        front = sorted((d for d in self.decorations if d.level > 0), key=lambda d: d.level)
        items += [_decoration_item(d) for d in behind]
        poses = self.physics.poses()
        at = {id(ob): pose for ob, pose in zip(self.physics.objects, poses)}
        for s in self.physics.springs.live():   # under the objects they join, as PGE draws them
            if s.colour is not None and id(s.a) in at and id(s.b) in at:
                items.append(spring_item(at[id(s.a)], at[id(s.b)], s.width, s.colour.rgb255()))
        for ob, pose in zip(self.physics.objects, poses):
            if ob.visible:
                colour = self.collision_colour if ob.name in self.flash else self.tint.get(ob.name, ob.colour)
                items.append(body_item(ob.state.local, ob.state.radius, pose, colour.rgb255(ob.alpha)))
        items += [_decoration_item(d) for d in front]
        self.flash.clear()
        self.tint.clear()
        return Frame(self.now, tuple(items))

    def _show(self, frame: Frame) -> None:
        """Live: wait for the frame's wall time (slowed down), show it, handle pygame's events."""
        import pygame

        from ..render.items import image

        size = self.resolution or 640
        if self.window is None:
            pygame.display.init()
            pygame.font.init()
            self.window = pygame.display.set_mode((size, size))
            pygame.display.set_caption("max2code pge")
            self.wall0 = wallclock.monotonic() - frame.time * self.slow
        wait = self.wall0 + frame.time * self.slow - wallclock.monotonic()
        if wait > 0:
            wallclock.sleep(wait)
        img = image(frame, size, size)
        self.window.blit(pygame.image.frombuffer(img.tobytes(), img.size, "RGB"), (0, 0))
        pygame.display.flip()
        for e in pygame.event.get():
            name = pygame.event.event_name(e.type).upper()
            if e.type in self.handlers or e.type == pygame.QUIT:
                self.input(_TYPE_NAMES.get(e.type, name), _attrs(e))


def spring_item(a, b, width: float, colour) -> Item:
    """A spring drawn as a straight band `width` wide between its ends' centres."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy) or 1.0
    ox, oy = -dy / n * width / 2, dx / n * width / 2
    return Item("polygon", colour, ((a[0] + ox, a[1] + oy), (b[0] + ox, b[1] + oy),
                                    (b[0] - ox, b[1] - oy), (a[0] - ox, a[1] - oy)))


def _decoration_item(d: Decoration) -> Item:
    colour = d.colour.rgb255()
    if d.kind == "text":
        return Item("text", colour, d.points, text=d.text, size=d.size)
    if d.kind == "circle":
        return Item("circle", colour, d.points, d.radius)
    return Item("polygon", colour, d.points)


# the pygame event types a game registers handlers for, by their pygame.locals names
INPUT_TYPES = ("QUIT", "KEYDOWN", "KEYUP", "MOUSEBUTTONDOWN", "MOUSEBUTTONUP", "MOUSEMOTION")
_TYPE_NAMES: dict[int, str] = {}


def _attrs(e) -> dict:
    """The attributes of a live pygame event that its handlers read (kept in the log)."""
    keep = ("key", "mod", "unicode", "pos", "button", "rel", "buttons")
    return {k: (list(v) if isinstance(v, tuple) else v) for k, v in e.dict.items() if k in keep}


_KEY_NAMES: dict[int, str] = {}


def key_name(code: int) -> str | int:
    """pygame's name of a key code (K_UP), which the log keeps: codes differ between pygame
    versions, names do not."""
    if not _KEY_NAMES:
        import pygame

        for name in dir(pygame):
            if name.startswith("K_"):
                _KEY_NAMES.setdefault(getattr(pygame, name), name)
    return _KEY_NAMES.get(code, code)


def init_type_names() -> None:
    import pygame

    for name in INPUT_TYPES:
        _TYPE_NAMES[getattr(pygame, name)] = name
