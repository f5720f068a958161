"""The objects a PGE game holds: colours, level-0 shapes (in the physics), decorations (other
levels: boxes, circles, polygons and text drawn behind or in front) and the events its callbacks
receive. Method names, arguments and chaining (`pge.box(...).fix().on_collision(f)`) are PGE's;
the behaviour is written from what PGE's documentation says each call does."""

from __future__ import annotations

import math
import os
import sys
from dataclasses import dataclass
from typing import Callable

from .physics import BodyState, PgeError

Vec = tuple[float, float]
_HERE = os.path.dirname(os.path.abspath(__file__))


def caller() -> str:
    """file:line of the game's code that made the current call (for error messages)."""
    f = sys._getframe(1)
    while f is not None and os.path.dirname(os.path.abspath(f.f_code.co_filename)) == _HERE:
        f = f.f_back
    return f"{f.f_code.co_filename}:{f.f_lineno}" if f is not None else "?"


@dataclass(frozen=True)
class Colour:
    """pge.rgb(r, g, b): components 0..1 (alpha 1 unless set_alpha gives a shape another)."""
    r: float
    g: float
    b: float

    def rgb255(self, alpha: float = 1.0) -> tuple[int, int, int, int]:
        clip = lambda v: max(0, min(255, int(v * 255.0)))  # noqa: E731 (PGE's own rounding: down)
        return clip(self.r), clip(self.g), clip(self.b), clip(alpha)


def _colour(c: object, call: str) -> Colour:
    if not isinstance(c, Colour):
        raise PgeError(f"{call}: expected a colour (pge.rgb), not {type(c).__name__}")
    return c


class Event:
    """What a callback receives: a collision (collision_between) or a timer (get_timer_id,
    cancel, was_cancelled)."""

    def __init__(self, kind: str, time: float, between: list | None = None,
                 timer_id: int | None = None, point: Vec | None = None) -> None:
        self.kind, self.time, self._between, self._timer = kind, time, between, timer_id
        self.point = point
        self._cancelled = False

    def collision_between(self) -> list:
        if self._between is None:
            raise PgeError("collision_between: this is not a collision event")
        return list(self._between)

    def cancel(self) -> None:
        self._cancelled = True

    def was_cancelled(self) -> bool:
        return self._cancelled

    def get_timer_id(self) -> int | None:
        return self._timer


class Shape:
    """A level-0 box, polygon or circle: a body of the physics."""

    def __init__(self, game, kind: str, state: BodyState, colour: Colour) -> None:
        self._game = game
        self.kind = kind
        self.name = f"{kind}-{len(game.shapes)}"
        self.state = state
        self.colour = colour
        self.alpha = 1.0
        self.fixed = False
        self.kg: float | None = None
        self.acc: Vec = (0.0, 0.0)
        self.removed = False
        self.visible = True
        self.body: int | None = None
        self.where = caller()
        self.param = None
        self.width = None
        self.collision_with: list = []
        self.collision_p: Callable | None = None

    # -- physics ---------------------------------------------------------------------------

    def _alive(self, call: str) -> None:
        if self.removed:
            raise PgeError(f"{call}: {self.name} has been deleted (rm)")

    def fix(self) -> "Shape":
        self._alive("fix")
        if not self.fixed:
            self._game.physics.touch()
            self.fixed = True
        return self

    def unfix(self) -> "Shape":
        self._alive("unfix")
        if self.fixed:
            self._game.physics.touch()
            self.fixed = False
        return self

    def is_fixed(self) -> bool:
        return self.fixed

    def mass(self, m: float) -> "Shape":
        self._alive("mass")
        if m is None or not (float(m) > 0 and math.isfinite(m)):
            raise PgeError(f"mass: expected a positive mass, not {m!r}")
        self._game.physics.touch()
        self.kg = float(m)
        return self

    def get_mass(self) -> float | None:
        return self.kg

    def velocity(self, vx: float, vy: float) -> "Shape":
        self._alive("velocity")
        self._game.physics.set_velocity(self, vx, vy)
        return self

    def accel(self, ax: float, ay: float) -> "Shape":
        """The object's own acceleration, on top of gravity."""
        self._alive("accel")
        self._game.physics.touch()
        self.acc = (float(ax), float(ay))
        return self

    def apply_impulse(self, unit_vec, magnitude) -> "Shape":
        self._alive("apply_impulse")
        if unit_vec is None or magnitude is None:
            return self
        self._game.physics.impulse(self, float(unit_vec[0]), float(unit_vec[1]), float(magnitude))
        return self

    def rm(self) -> None:
        if not self.removed:
            self._game.remove(self)

    def get_xpos(self) -> float:
        return self._game.physics.pose(self)[0]

    def get_ypos(self) -> float:
        return self._game.physics.pose(self)[1]

    def get_unit_coord(self) -> list[float]:
        if self.kind != "circle":
            raise PgeError(f"get_unit_coord: {self.name} is not a circle")
        x, y, _ = self._game.physics.pose(self)
        return [x, y]

    def get_xvel(self) -> float:
        return self._game.physics.velocity(self)[0]

    def get_yvel(self) -> float:
        return self._game.physics.velocity(self)[1]

    def put_xvel(self, f: float) -> None:
        self._alive("put_xvel")
        self._game.physics.set_velocity(self, f, self.get_yvel())

    def put_yvel(self, f: float) -> None:
        self._alive("put_yvel")
        self._game.physics.set_velocity(self, self.get_xvel(), f)

    def get_xaccel(self) -> float:
        return self.acc[0]

    def get_yaccel(self) -> float:
        return self.acc[1]

    def put_xaccel(self, f: float) -> None:
        self.accel(float(f), self.acc[1])

    def put_yaccel(self, f: float) -> None:
        self.accel(self.acc[0], float(f))

    def moving_towards(self, x: float, y: float) -> bool:
        if self.fixed:
            return False
        px, py, _ = self._game.physics.pose(self)
        vx, vy, _ = self._game.physics.velocity(self)
        return (x - px) * vx + (y - py) * vy > 0

    # -- callbacks -------------------------------------------------------------------------

    def on_collision_with(self, another: list, p: Callable) -> "Shape":
        self.collision_p, self.collision_with = p, list(another)
        return self

    def on_collision(self, p: Callable) -> "Shape":
        return self.on_collision_with([], p)

    def collided(self, between: list, event: Event) -> None:
        """PGE's rule: with no list, every collision calls p(self, event); with one, only those
        with an object of the list."""
        if self.collision_p is None:
            return
        if not self.collision_with or any(o in self.collision_with for o in between):
            self.collision_p(self, event)

    # -- user data and looks ---------------------------------------------------------------

    def get_param(self):
        return self.param

    def set_param(self, value) -> "Shape":
        self.param = value
        return self

    def set_width(self, value) -> None:
        self.width = value

    def get_width(self):
        return self.width

    def get_colour(self) -> Colour:
        return self.colour

    def set_colour(self, c: Colour) -> "Shape":
        self.colour = _colour(c, "set_colour")
        return self

    def set_alpha(self, value: float) -> "Shape":
        self.alpha = float(value)
        return self

    def set_visible(self, value: bool) -> "Shape":
        self.visible = bool(value)
        return self

    def __repr__(self) -> str:
        return f"<pge {self.name}>"


class Decoration:
    """A box, polygon, circle or text at a level other than 0: drawn (levels below 0 behind the
    shapes, above 0 in front), never in the physics."""

    def __init__(self, game, kind: str, level: int, colour: Colour, points: tuple[Vec, ...] = (),
                 radius: float = 0.0, text: str = "", size: int = 0) -> None:
        self._game, self.kind, self.level = game, kind, level
        self.colour, self.points, self.radius = colour, points, radius
        self.text, self.size = text, size
        self.removed = False
        self.param = None

    def rm(self) -> None:
        if not self.removed:
            self.removed = True
            self._game.decorations.remove(self)

    def get_colour(self) -> Colour:
        return self.colour

    def set_colour(self, c: Colour) -> "Decoration":
        self.colour = _colour(c, "set_colour")
        return self

    def get_param(self):
        return self.param

    def set_param(self, value) -> "Decoration":
        self.param = value
        return self

    def __getattr__(self, name: str):
        if name.startswith("_"):
            raise AttributeError(name)
        if hasattr(Shape, name):
            raise PgeError(f"{name}: a {self.kind} at level {self.level} is not in the physics "
                           "(only level-0 objects are)")
        raise AttributeError(name)
