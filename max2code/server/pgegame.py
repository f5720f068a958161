"""A PGE program served: `max2code serve GAME.py` (docs/server.md, "Serving a PGE game").

The program runs as under `max2code pge` until its first `pge.run()`, which under serve hands
the built game over instead of looping and waits (pge.game.Options.serve). From then on the room steps
it: GameWorld below shows the room the part of the World API it uses, with PGE's objects as
bodies. Ids on the wire are the objects' order of creation (stable, never reused), because PGE
rebuilds its engine World on structural changes (fix, mass, a new object), which renumbers the
engine's bodies; a rebuild counts as a change of every body. The game's timers (at_time) and
collision callbacks run inside the room's steps; a client's keys reach the game's handlers
(register_handler) as pygame KEYDOWN/KEYUP events at the server's time.

The program itself runs in a thread of its own, strictly alternating with the room (Program):
code after a run() goes on at that run's end, as under `max2code pge`.

Not served: PGE's decorations (text, objects off level 0) and colour changes after the start.
"""

from __future__ import annotations

import math
import os
import threading
from dataclasses import dataclass, replace

from ..engine.world import BodyInfo, EngineError
from ..pge.game import Game, GameOver, Options

UNIT_VIEW = (0.0, 0.0, 1.0, 1.0)   # PGE's world is the unit square
KEY_NAMES = {"left": "K_LEFT", "right": "K_RIGHT", "up": "K_UP", "down": "K_DOWN"}


@dataclass(frozen=True)
class GameEvent:
    """What the room reads of an event: its time, kind and bodies (wire ids; b = -1: none)."""
    time: float
    kind: str
    a: int
    b: int = -1


class Program:
    """The program in a thread of its own, strictly alternating with the room: it runs until
    it calls pge.run(t), then waits while the room steps the game to the run's end, then goes
    on (breakout's `out_of_time` after its `run(10.0)`) until its next run() or its end. Only
    one of the two ever runs, so the game is never touched by both at once."""

    def __init__(self, path: str) -> None:
        os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
        os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
        os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
        self.path = path
        self.game: Game | None = None
        self.end = math.inf              # the current run()'s end (game time)
        self.code: int | None = None     # the program's exit status once it ended
        self.failure: BaseException | None = None
        self._to_room = threading.Event()
        self._to_program = threading.Event()
        threading.Thread(target=self._main, name=f"pge {os.path.basename(path)}", daemon=True).start()
        self._to_room.wait()
        self._to_room.clear()
        if self.failure is not None:
            raise self.failure
        if self.game is None:
            raise EngineError(f"{path}: the program ended (exit {self.code}) without calling pge.run()")

    def _main(self) -> None:
        from ..pge.command import run_game

        try:
            self.code, _ = run_game(self.path, Options(headless=True, serve=self._handed))
        except BaseException as exc:   # the game's own error: the room (or load) reports it
            self.failure, self.code = exc, 1
        self._to_room.set()

    def _handed(self, game: Game, end: float) -> None:
        """pge.run(t) under serve, in the program's thread: wait for the room."""
        self.game, self.end = game, end
        self._to_room.set()
        self._to_program.wait()
        self._to_program.clear()

    def resume(self) -> None:
        """The room reached the run's end: the program goes on to its next run() or its end."""
        self._to_program.set()
        self._to_room.wait()
        self._to_room.clear()


def load(path: str) -> Program:
    """The program run to its first pge.run() (or the exception it failed with)."""
    return Program(path)


def _hex(colour) -> str:
    return "#%02x%02x%02x" % colour.rgb255()[:3]


class GameWorld:
    """A handed-over PGE game with the World calls a Room makes (bodies, time, step_to,
    motions, next_time, pose, velocity) and `input` for its handlers."""

    def __init__(self, program: Program) -> None:
        self.program = program
        self.game = program.game
        self.objects: list = []          # by wire id
        self._wire: dict[int, int] = {}  # id(object) -> wire id
        self.bodies: list[BodyInfo] = []
        self._accel: list[tuple[float, float]] = []
        self._log = len(self.game.log)
        self._core = None                # the engine World last read (a rebuild replaces it)
        self._base: list[int] = []       # counters carried over rebuilds
        self._last: list[int] = []
        self._held: list[tuple[float, ...]] = []
        self.over: int | None = None
        self._sync()

    # -- the objects as bodies ------------------------------------------------------------------

    def _sync(self) -> None:
        """New objects get the next ids; removed ones are marked dead."""
        physics = self.game.physics
        for ob in physics.objects:
            if id(ob) not in self._wire and ob.body is not None:
                i = len(self.objects)
                self._wire[id(ob)] = i
                self.objects.append(ob)
                info = physics.world.bodies[ob.body]
                self.bodies.append(replace(info, id=i, name=ob.name, color=_hex(ob.colour)))
                self._accel.append(physics.gravity)
                self._base.append(0)
                self._last.append(-1)
                self._held.append(self._motion(ob))
        for i, ob in enumerate(self.objects):
            if ob.removed and self.bodies[i].alive:
                self.bodies[i] = replace(self.bodies[i], alive=False)

    def _motion(self, ob) -> tuple[float, ...]:
        physics = self.game.physics
        m = physics.world.motions()[0][ob.body]
        return (m[0] + physics.t0,) + tuple(m[1:])

    @property
    def time(self) -> float:
        return self.game.now

    def alive(self, i: int) -> bool:
        return self.bodies[i].alive

    def motions(self) -> tuple[list[tuple[float, ...]], list[int]]:
        physics = self.game.physics
        world = physics.world
        motions, counters = world.motions()
        rebuilt = world is not self._core
        self._core = world
        out = []
        for i, ob in enumerate(self.objects):
            if ob.body is not None and not ob.removed and not physics.stale:
                c = counters[ob.body]
                if rebuilt:   # new engine ids: every body's motion counts as changed
                    self._base[i] += self._last[i] + 2
                self._last[i] = c
                m = motions[ob.body]
                self._held[i] = (m[0] + physics.t0,) + tuple(m[1:])
            out.append(self._base[i] + max(self._last[i], 0))
        return list(self._held), out

    def acceleration(self, i: int) -> tuple[float, float]:
        """The object's gravity (PGE's is the game's, set before its objects move)."""
        return self._accel[i]

    def pose(self, i: int, t: float | None = None):
        return self.game.physics.pose(self.objects[i])

    def velocity(self, i: int, t: float | None = None):
        return self.game.physics.velocity(self.objects[i])

    def next_time(self) -> float:
        if self.over is not None:
            return math.inf
        physics = self.game.physics
        t = physics.world.next_time() + physics.t0 if not physics.stale else self.time
        queue = self.game.queue
        return min(t, queue[0].time if queue else math.inf, self.program.end)

    # -- stepping ---------------------------------------------------------------------------------

    def _run(self, action) -> list[GameEvent]:
        """Run a step of the game with `pge` calls going to it; its collisions as events."""
        from .. import pge

        if self.over is not None:
            raise EngineError(f"the game ended (exit {self.over})")
        with pge.playing(self.game):
            try:
                action()
            except GameOver as over:
                self.over = over.code
            except SystemExit as exc:
                self.over = exc.code if isinstance(exc.code, int) else 1
            except Exception as exc:   # the game's own error (a callback's, or its program's)
                from ..pge.command import game_error

                self.over = 1
                raise EngineError(game_error(self.program.path, exc)) from None
        self._sync()
        events = []
        for rec in self.game.log[self._log:]:
            if rec["kind"] == "collision":
                a, b = (self._named(rec["a"]), self._named(rec["b"]))
                events.append(GameEvent(rec["t"], "collision", a, b))
        self._log = len(self.game.log)
        if self.over is not None and not events:
            raise EngineError(f"the game ended (exit {self.over})")
        return events

    def _named(self, name: str) -> int:
        for i, ob in enumerate(self.objects):
            if ob.name == name:
                return i
        return -1

    def step_to(self, t: float, events: bool = True) -> list[GameEvent]:
        """Timers and collisions up to t; at the end of the program's run(), the program goes
        on (with `pge` pointing at this game) until its next run() or its end."""
        game, program = self.game, self.program

        def go():
            while True:
                target = min(t, program.end)
                while game.queue and game.queue[0].time <= target:
                    game.physics.advance(max(game.queue[0].time, game.now))
                    game.fire_next()
                game.physics.advance(target)
                if target < program.end:
                    return
                program.resume()
                if program.failure is not None:
                    raise program.failure
                if program.code is not None:
                    raise GameOver(program.code)
        return self._run(go)

    def input(self, kind: str, key: str) -> None:
        """A client's key as the game's pygame event, now."""
        import pygame

        self._run(lambda: self.game.input(kind, {"key": getattr(pygame, KEY_NAMES[key])}))
