"""PGE's Python API on the predictive engine: `import pge` in a PGE game resolves here when the
game runs under `max2code pge GAME.py` (docs/games.md).

Written from what PGE's API does (its documented calls, arguments and chaining), not from its
code. Every call PGE has is here: the supported ones act, the others (sound, the
recording file) raise PgeError naming the call, never silently do nothing. COVERAGE lists
which is which, for the documentation and its test.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Callable

from .game import Game, GameOver, Options
from .objects import Colour, Decoration, Event, Shape
from .physics import PgeError, circle_state, polygon_state

_game = Game()


def _start(options: Options) -> Game:
    """A fresh game (the command calls this before running the program)."""
    global _game
    _game = Game(options)
    return _game


def current() -> Game:
    return _game


@contextmanager
def playing(game: Game) -> Iterator[Game]:
    """`pge` calls go to `game` inside the block, to the game before it after (the server runs
    one game per room: max2code/server/pgegame.py)."""
    global _game
    saved, _game = _game, game
    try:
        yield game
    finally:
        _game = saved


def _unsupported(call: str, why: str) -> PgeError:
    return PgeError(f"unsupported: {call} ({why})")


# -- colours and objects ----------------------------------------------------------------------

def rgb(r: float, g: float, b: float) -> Colour:
    return Colour(float(r), float(g), float(b))


def white() -> Colour:
    return Colour(1.0, 1.0, 1.0)


def _colour(c, call: str) -> Colour:
    if not isinstance(c, Colour):
        raise PgeError(f"{call}: expected a colour (pge.rgb), not {type(c).__name__}")
    return c


def _poly(call: str, coords: tuple, c, level: int):
    colour = _colour(c, call)
    pts = [(float(coords[i]), float(coords[i + 1])) for i in range(0, len(coords), 2)]
    if level == 0:
        return _game.add(Shape(_game, "box" if call == "box" else call, polygon_state(pts), colour))
    d = Decoration(_game, "polygon", level, colour, tuple(pts))
    _game.decorations.append(d)
    return d


def box(x: float, y: float, w: float, h: float, c, level: int = 0):
    """A w x h box with its lower left corner at (x, y)."""
    ob = _poly("box", (x, y, x + w, y, x + w, y + h, x, y + h), c, level)
    if level == 0:
        ob.set_width(w)
    return ob


def poly3(x0, y0, x1, y1, x2, y2, c, level: int = 0):
    return _poly("poly3", (x0, y0, x1, y1, x2, y2), c, level)


def poly4(x0, y0, x1, y1, x2, y2, x3, y3, c, level: int = 0):
    return _poly("poly4", (x0, y0, x1, y1, x2, y2, x3, y3), c, level)


def circle(x: float, y: float, r: float, c, level: int = 0):
    colour = _colour(c, "circle")
    if level == 0:
        return _game.add(Shape(_game, "circle", circle_state(x, y, r), colour))
    d = Decoration(_game, "circle", level, colour, ((float(x), float(y)),), float(r))
    _game.decorations.append(d)
    return d


def text(x: float, y: float, s: str, c, size: int, level: int) -> Decoration:
    colour = _colour(c, "text")
    if level == 0:
        raise PgeError("text: not allowed at level 0 (text is never in the physics)")
    d = Decoration(_game, "text", level, colour, ((float(x), float(y)),), text=str(s), size=int(size))
    _game.decorations.append(d)
    return d


def spring(ob1, ob2, k, d, l=None):
    """A damped spring between the centres of mass of two level-0 objects (stiffness k,
    damping d along the spring, rest length l: default their distance now). Returns the
    spring (draw, end, mid, when, rm)."""
    return _game.add_spring(ob1, ob2, k, d, l)


# -- the world and time -----------------------------------------------------------------------

def gravity(value: float = -9.81) -> None:
    _game.physics.touch()
    _game.physics.gravity = (0.0, float(value))


def at_time(t: float, p: Callable) -> int:
    """Call p(event, None) t seconds (divided by slow_down) from now; returns the timer's id."""
    return _game.at_time(t, p)


def at_cancel(i: int) -> None:
    _game.at_cancel(i)


def run(t: float = -1) -> None:
    _game.run(t)


def slow_down(t: float) -> None:
    if not (float(t) > 0 and math.isfinite(t)):
        raise PgeError(f"slow_down: expected a positive factor, not {t!r}")
    _game.slow = float(t)


def fps(f: float) -> None:
    if not (float(f) > 0 and math.isfinite(f)):
        raise PgeError(f"fps: expected a positive rate, not {f!r}")
    _game.game_fps = float(f)


def get_frame_no() -> int:
    return _game.frame_no


def local_fps() -> None:
    """Show the frames drawn in each second, top right, updated every second."""
    state = {"last": _game.frame_no, "text": None}

    def update(e=None, o=None):
        if state["text"] is not None:
            state["text"].rm()
        state["text"] = text(0.8, 0.1, "fps %d" % (_game.frame_no - state["last"]), white(), 50, 1)
        state["last"] = _game.frame_no
        at_time(1.0, update)

    at_time(1.0, update)


# -- the display and input --------------------------------------------------------------------

def register_handler(function: Callable, pyeventlist) -> None:
    for e in pyeventlist:
        _game.handlers[e] = function


def deregister_handler(pyeventlist) -> None:
    for e in pyeventlist:
        if e not in _game.handlers:
            raise PgeError(f"deregister_handler: no handler for event type {e}")
        del _game.handlers[e]


def display_set_mode(r) -> None:
    """The window's size: PGE's window is square, r[0] wide (r[1] becomes r[0], as in PGE)."""
    r[1] = r[0]
    _game.resolution = int(r[0])


def display_fullscreen(b: bool) -> None:
    _game.fullscreen = bool(b)


def pyg_to_unit_coord(v) -> list[float]:
    if not _game.resolution:
        raise PgeError("pyg_to_unit_coord: call display_set_mode first")
    res = _game.resolution
    return [float(v[0]) / res, float(res - v[1]) / res]


def draw_collision(actual: bool, predict: bool) -> None:
    """actual: objects in a collision are drawn in the collision colour in the next frame."""
    if predict:
        raise _unsupported("draw_collision(predict=True)", "frames of predicted collisions")
    _game.draw_actual = bool(actual)


def collision_colour(c) -> None:
    _game.collision_colour = _colour(c, "collision_colour")


def batch() -> None:
    """Device choice: `max2code pge --headless` decides it, whatever the game asks."""


def interactive() -> None:
    """Device choice: `max2code pge` (without --headless) decides it, whatever the game asks."""


def record() -> None:
    """Recording: the frames go to --gif, --mp4 or --png-dir (PGE's output.raw is not made)."""


def finish_record() -> None:
    """(see record)"""


def dump_world() -> None:
    """A textual dump of the level-0 objects, one per line."""
    for ob in _game.physics.objects:
        x, y, a = _game.physics.pose(ob)
        vx, vy, _ = _game.physics.velocity(ob)
        kind = "fixed" if ob.fixed else f"mass {ob.kg:g}"
        print(f"{ob.name}: {kind} at ({x:.6g}, {y:.6g}) angle {a:.6g} velocity ({vx:.6g}, {vy:.6g})")


def play(name) -> None:
    raise _unsupported("play", "sound")


def message(text) -> None:
    raise _unsupported("message", "PGE's output.raw recording file")


def delay(t) -> None:
    raise _unsupported("delay", "PGE's output.raw recording file")


# -- vectors ----------------------------------------------------------------------------------

def magnitude(v) -> float:
    return math.hypot(v[0], v[1])


def normalise(v) -> list[float]:
    n = magnitude(v)
    return [float(v[0]) / n, float(v[1]) / n]


def sub_coord(a, b) -> list[float]:
    return [a[0] - b[0], a[1] - b[1]]


# Every call of PGE's API: True where it acts here, else the reason it raises "unsupported".
COVERAGE: dict[str, str | bool] = {
    **{name: True for name in (
        "rgb", "white", "box", "poly3", "poly4", "circle", "text", "gravity", "at_time",
        "at_cancel", "run", "slow_down", "fps", "get_frame_no", "local_fps", "register_handler",
        "deregister_handler", "display_set_mode", "display_fullscreen", "pyg_to_unit_coord",
        "draw_collision", "collision_colour", "batch", "interactive", "record", "finish_record",
        "dump_world", "magnitude", "normalise", "sub_coord",
        "object.fix", "object.unfix", "object.is_fixed", "object.mass", "object.get_mass",
        "object.velocity", "object.accel", "object.apply_impulse", "object.rm",
        "object.on_collision", "object.on_collision_with", "object.get_xpos", "object.get_ypos",
        "object.get_unit_coord", "object.get_xvel", "object.get_yvel", "object.put_xvel",
        "object.put_yvel", "object.get_xaccel", "object.get_yaccel", "object.put_xaccel",
        "object.put_yaccel", "object.moving_towards", "object.get_param", "object.set_param",
        "object.set_width", "object.get_width", "object.get_colour", "object.set_colour",
        "object.set_alpha", "object.set_visible", "event.collision_between", "event.cancel",
        "event.was_cancelled", "event.get_timer_id")},
    "spring": True, "object.draw": True, "object.end": True, "object.mid": True,
    "object.when": True,
    "draw_collision(predict=True)": "frames of predicted collisions",
    "play": "sound", "message": "PGE's output.raw file", "delay": "PGE's output.raw file",
}

__all__ = ["PgeError", "GameOver", "Event", "COVERAGE"] + [
    n for n in COVERAGE if "." not in n and "(" not in n]
