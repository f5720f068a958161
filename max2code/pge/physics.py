"""PGE's level-0 objects in a max2code.engine World: building, editing at the current time, stepping.

PGE lets a game change anything at any time: remove an object (a brick that was hit), fix or
unfix it, give it a mass after it was made, add objects while the game runs. Changes the World
takes in place (a dynamic body's new velocity, a removal) go straight to it. Other structural
changes (fix/unfix, mass, acceleration, a new object) mark the world stale: every body's exact state is
read out at that instant, and the world is rebuilt from those states before time moves on
(O(bodies) once per change, at the change's exact time, so nothing is approximated). Game time
is the rebuilt world's time plus the time it was rebuilt at.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Protocol

from ..engine.shapes import mass_properties, polygon_area
from ..engine.world import Event, World
from .signals import Rebuild, WindowEnd
from .springs import Springs

Vec = tuple[float, float]
TOLERANCE = 1e-9  # lengths in PGE's unit square
RESTITUTION = 1.0  # PGE's collisions are elastic


class PgeError(Exception):
    """A PGE call the game made wrongly, or one this module does not support (the message names
    the call)."""


@dataclass
class BodyState:
    """A body's shape in its own frame and its state at the time it was last read out."""
    local: tuple[Vec, ...]   # vertices about the reference point (one vertex: a circle)
    radius: float
    x: float
    y: float
    angle: float = 0.0
    vx: float = 0.0
    vy: float = 0.0
    omega: float = 0.0


def polygon_state(points: list[Vec]) -> BodyState:
    """A polygon given in world coordinates, in either winding (PGE accepts both), about its
    centroid."""
    if polygon_area(points) < 0:
        points = points[::-1]
    c = mass_properties(points, 0.0).centroid
    return BodyState(tuple((x - c[0], y - c[1]) for x, y in points), 0.0, c[0], c[1])


def circle_state(x: float, y: float, r: float) -> BodyState:
    return BodyState(((0.0, 0.0),), float(r), float(x), float(y))


class Physical(Protocol):
    """What the physics needs of a PGE object (max2code.pge.objects.Shape)."""
    name: str
    state: BodyState
    fixed: bool
    kg: float | None
    acc: Vec
    removed: bool
    body: int | None
    where: str


class Physics:
    """The World behind a PGE game and the objects in it (ids are positions in `bodies`)."""

    def __init__(self) -> None:
        self.world: World | None = None
        self.t0 = 0.0
        self.gravity: Vec = (0.0, 0.0)
        self.objects: list[Physical] = []
        self.bodies: list[Physical] = []
        self.stale = True
        self.rebuilds = 0
        self.on_contact: Callable[[Physical, Physical, Event, float], None] | None = None
        self.springs = Springs()

    # -- time -------------------------------------------------------------------------------

    @property
    def now(self) -> float:
        return self.t0 + (self.world.time if self.world is not None else 0.0)

    def advance(self, t: float) -> None:
        """Process every collision up to game time t (callbacks at their times)."""
        while True:
            if self.stale:
                self._build()
            try:
                if self.springs.active():
                    self.springs.advance(self, t)   # windows: max2code.pge.springs
                else:
                    self.world.step_to(t - self.t0, events=False)
                return
            except Rebuild:
                continue

    # -- edits ------------------------------------------------------------------------------

    def add(self, ob: Physical) -> None:
        self.touch()
        ob.body = None
        self.objects.append(ob)

    def touch(self) -> None:
        """The world no longer matches the objects: read every body's exact state out now."""
        if self.stale:
            return
        for ob in self.bodies:
            if ob.body is not None:
                s = ob.state
                s.x, s.y, s.angle = self.world.pose(ob.body)
                s.vx, s.vy, s.omega = self.world.velocity(ob.body)
        self.stale = True

    def remove(self, ob: Physical) -> None:
        """At once, by the engine's own removal (also inside a collision callback) when the
        world is current; the object keeps the pose it had."""
        if not self.stale and ob.body is not None:
            s = ob.state
            s.x, s.y, s.angle = self.world.pose(ob.body)
            s.vx, s.vy, s.omega = self.world.velocity(ob.body)
            self.world.remove(ob.body)
        else:
            self.touch()
        ob.removed = True
        ob.body = None  # (its pose stays the one it had when removed)
        self.objects.remove(ob)

    def set_velocity(self, ob: Physical, vx: float, vy: float) -> None:
        """A fixed object keeps the velocity for when it is unfixed."""
        if self.stale or ob.body is None or ob.fixed:
            ob.state.vx, ob.state.vy = float(vx), float(vy)
            return
        omega = self.world.velocity(ob.body)[2]
        self.world.set_velocity(ob.body, (float(vx), float(vy)), omega)

    def pose(self, ob: Physical) -> tuple[float, float, float]:
        if self.stale or ob.body is None:
            return ob.state.x, ob.state.y, ob.state.angle
        return self.world.pose(ob.body)

    def velocity(self, ob: Physical) -> tuple[float, float, float]:
        if self.stale or ob.body is None:
            return ob.state.vx, ob.state.vy, ob.state.omega
        return self.world.velocity(ob.body)

    def poses(self) -> list[tuple[float, float, float]]:
        """Every object's pose now, in `objects` order (one call into the core when current)."""
        if self.stale:
            return [(o.state.x, o.state.y, o.state.angle) for o in self.objects]
        flat = self.world.poses()
        return [flat[o.body] for o in self.objects]

    # -- the world --------------------------------------------------------------------------

    def _build(self) -> None:
        t = self.now
        w = World(gravity=self.gravity, tolerance=TOLERANCE)
        self.bodies = []
        sprung = {id(o) for o in self.springs.sprung()}
        for ob in self.objects:
            if not ob.fixed and not ob.kg:
                raise PgeError(f"{ob.name} (made at {ob.where}) is not fixed and has no mass: "
                               "every moving object needs .mass(m) (or .fix())")
            s = ob.state
            common = dict(radius=s.radius, position=(s.x, s.y), angle=s.angle,
                          restitution=RESTITUTION, name=ob.name,
                          group=ob.name if id(ob) in sprung else None)  # (its twin sensor's)
            if ob.fixed:
                ob.body = w.add_body(s.local, kind="static", **common)
            else:
                g = (self.gravity[0] + ob.acc[0], self.gravity[1] + ob.acc[1])
                ob.body = w.add_body(s.local, kind="dynamic", velocity=(s.vx, s.vy),
                                     omega=s.omega, mass=float(ob.kg), gravity=g, **common)
                # (the engine moved the reference point to the centre of mass: keep its frame)
                info = w.bodies[ob.body]
                s.local = info.vertices
                s.x, s.y, s.angle = w.pose(ob.body)
            self.bodies.append(ob)
        w.on_collision(self._collided)
        self.world, self.t0, self.stale = w, t, False
        self.rebuilds += 1

    def _collided(self, world: World, ev: Event) -> None:
        if ev.kind == "sensor" and (self.springs.is_sensor(ev.a) or self.springs.is_sensor(ev.b)):
            raise WindowEnd()  # a sprung body may touch something: a tighter window from here
        if ev.kind != "collision":
            return
        if self.on_contact is not None:
            self.on_contact(self.bodies[ev.a], self.bodies[ev.b], ev, self.t0 + ev.time)
        if self.stale:
            raise Rebuild()
        if self.springs.in_window(ev.a) or self.springs.in_window(ev.b):
            raise WindowEnd()  # a sprung body's path changed: a new window from its new state

    def impulse(self, ob: Physical, ux: float, uy: float, magnitude: float) -> None:
        """An impulse of `magnitude` along (ux, uy) through the centre of mass."""
        if ob.fixed or not ob.kg:
            return
        n = math.hypot(ux, uy) or 1.0
        vx, vy, _ = self.velocity(ob)
        k = magnitude / (n * float(ob.kg))
        self.set_velocity(ob, vx + k * ux, vy + k * uy)
