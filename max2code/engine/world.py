"""The Python face of the C engine: a World of bodies, stepped from event to event."""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, replace
from typing import Callable, Iterable, Iterator, Sequence

from . import limits
from .binding import load
from .handlers import FLAG_SENSOR, CollisionHandler, Handlers
from .geometry import transform
from .inputs import Input
from .limits import CONTACT_STEP
from .shapes import MassProperties, compound_mass_properties, mass_properties, polygon_area

Vec = tuple[float, float]
KINDS = {"static": 0, "kinematic": 1, "dynamic": 2}
EVENT_KINDS = {0: "presolve", 1: "collision", 2: "rest", 3: "wake", 4: "timer", 5: "sensor",
               6: "separate", 7: "sensor_leave"}
BUFFER = 1024


class EngineError(RuntimeError):
    """The engine refused something (the message is the C core's)."""


@dataclass(frozen=True)
class BodyInfo:
    """What the engine holds about a body, in its own frame: `vertices` are offsets from the
    reference point (a dynamic body's centre of mass), as `pose()` reports it."""
    id: int
    name: str
    kind: str
    vertices: tuple[Vec, ...]
    radius: float
    mass: float
    inertia: float
    restitution: float
    group: str | None
    color: str | None = None
    friction: float = 0.0
    category: int = 1
    mask: int = 0xFFFFFFFF
    data: object = None
    alive: bool = True
    collision_type: int = 0
    sensor: bool = False
    parts: tuple[tuple[tuple[Vec, ...], float], ...] = ()   # a compound's (vertices, radius)

    @property
    def shape(self) -> str:
        if self.parts:
            return "compound"
        n = len(self.vertices)
        return "circle" if n == 1 else ("capsule" if self.radius > 0 else "segment") if n == 2 else "polygon"

    @property
    def shapes(self) -> tuple[tuple[tuple[Vec, ...], float], ...]:
        """Every convex shape of the body as (vertices, radius) in its frame: a compound's
        parts, or the one shape."""
        return self.parts or ((self.vertices, self.radius),)

    def mass_properties(self) -> MassProperties:
        """Area, centroid and inertia per unit mass of the body's shape (all its parts)."""
        if self.parts:
            return compound_mass_properties([(list(v), r) for v, r in self.parts])
        return mass_properties(list(self.vertices), self.radius)


@dataclass(frozen=True)
class Event:
    """One reported event. `normal` points from body a towards body b; `speed` is the closing
    speed along it before the response and `impulse` the normal impulse given to b (-impulse
    to a). Timers have a = the timer's id and b = -1. `data` is the two bodies' user data
    (add_body's data=; a timer's: the data given to add_timer)."""
    time: float
    kind: str
    a: int
    b: int
    normal: Vec
    point: Vec
    speed: float
    impulse: float
    data: tuple[object, object] = (None, None)


@dataclass(frozen=True)
class RayHit:
    """The first shape a ray enters: its body, the point, the surface normal there and the
    fraction of the ray travelled (0..1)."""
    body: int
    point: Vec
    normal: Vec
    fraction: float


@dataclass
class _Timer:
    callback: Callable[["World", Event], None] | None
    data: object = None
    is_input: bool = False


def _anticlockwise(vertices: Sequence[Vec]) -> list[Vec]:
    """The vertices as floats, a clockwise polygon reversed (the core keeps them
    anticlockwise)."""
    verts = [(float(x), float(y)) for x, y in vertices]
    if len(verts) >= 3 and polygon_area(verts) < 0:
        verts.reverse()
    return verts


def _shape(where: str, vertices: Sequence[Vec], radius: object) -> tuple[list[Vec], float]:
    """One shape as (anticlockwise vertices, radius), every number checked (_number) before
    any conversion: float() would take "1" and overflow on 10**400."""
    try:
        points = list(vertices)
    except TypeError:
        raise EngineError(f"{where}vertices: expected (x, y) pairs, got "
                          f"{limits.shown(vertices)}") from None
    for j, p in enumerate(points):
        _vector(f"{where}vertices[{j}]", p)
    return _anticlockwise(points), _number(f"{where}radius", radius, nonneg=True)


def _parts(parts: Sequence[tuple[Sequence[Vec], float]]) -> list[tuple[list[Vec], float]]:
    """A compound's parts as (anticlockwise vertices, radius), a malformed one named (part k
    of n) rather than left to an unpacking error."""
    shapes = []
    for k, part in enumerate(parts):
        where = f"part {k} of {len(parts)}: "
        try:
            v, r = part
            if any(len(p) != 2 for p in v):
                raise ValueError
        except (TypeError, ValueError):
            shown = limits.shown(part, 60)
            raise EngineError(f"{where}expected (vertices, radius) with "
                              f"vertices (x, y) pairs, got {shown}") from None
        shapes.append(_shape(where, v, r))
    return shapes


def _number(name: str, v: object, **bounds: bool | float) -> float:
    """`v` as a float, or an EngineError naming the argument: the scene files' rule
    (limits.number_problem: finite, 0 or 1e-30 to 1e30 in magnitude, the quantity's own
    bounds), so that the API takes nothing a scene file refuses (issue 33)."""
    problem = limits.number_problem(v, **bounds)  # type: ignore[arg-type]
    if problem:
        raise EngineError(f"{name}: {problem}")
    return float(v)  # type: ignore[arg-type]


def _vector(name: str, v: object, check: Callable[[str, object], float] | None = None) -> Vec:
    """(x, y) as floats, each checked as _number (or `check`; named `name[0]`, `name[1]`)."""
    try:
        x, y = v  # type: ignore[misc]
    except (TypeError, ValueError):
        raise EngineError(f"{name}: expected (x, y), two numbers, got {limits.shown(v)}") from None
    check = check or _number
    return (check(f"{name}[0]", x), check(f"{name}[1]", y))


def _now(v: float) -> float:
    """A body's state (position, angle, velocity, omega, acceleration, an impulse: add_body,
    set_velocity, set_pose, set_acceleration, apply_impulse) with a magnitude below
    limits.SMALLEST is taken as 0 (the sign kept) rather than refused: games compute these
    every frame and feed the engine's own values back (PGE rebuilds its World from them), and
    a damped spring's speed passes 1e-30 after some 70 time constants; refusing it then would
    end the game, and to the engine's arithmetic it is 0."""
    return math.copysign(0.0, v) if abs(v) < limits.SMALLEST else v


def _now_number(name: str, v: object) -> float:
    """_number for a body's state: a magnitude below 1e-30 is 0 (_now)."""
    if isinstance(v, numbers.Real) and not isinstance(v, bool) and limits.finite(v):
        v = _now(float(v))
    return _number(name, v)


def _mask(name: str, bits: object) -> int:
    if (isinstance(bits, bool) or not isinstance(bits, numbers.Integral)
            or not 0 <= bits <= 0xFFFFFFFF):
        raise EngineError(f"{name}: a 32-bit mask (0 to 0xFFFFFFFF), not {limits.shown(bits)}")
    return int(bits)


def _mass_range(name: str, m: float, inertia: float, derived: bool, inertia_name: str) -> None:
    """A dynamic body's mass and inertia within what the engine's arithmetic holds
    (limits.MASS, limits.INERTIA: a mass of 1e308 once gave an infinite impulse), named by
    the argument they come from."""
    problem = limits.range_problem("mass (density x area)" if derived else "mass", m, limits.MASS)
    if problem:
        raise EngineError(f"{name}: {problem}")
    problem = limits.range_problem("moment of inertia", inertia, limits.INERTIA)
    if problem:
        raise EngineError(f"{inertia_name}: {problem}")


def _shape_mass(shapes: list[tuple[list[Vec], float]], compound: bool) -> MassProperties:
    """The mass properties of a body's shapes; a shape with no area where one is needed (a
    polygon with its vertices in a line, or none) is the core's error, said here first."""
    try:
        return compound_mass_properties(shapes) if compound else mass_properties(*shapes[0])
    except ZeroDivisionError:
        for k, (v, _) in enumerate(shapes):
            if len(v) == 0 or (len(v) >= 3 and polygon_area(v) == 0):
                where = f"part {k} of {len(shapes)}: " if compound else ""
                what = ("a body needs at least one vertex" if not v
                        else "a polygon must be convex (no three vertices in a line)")
                raise EngineError(where + what) from None
        raise


_NATIVE = frozenset({"_ffi", "_lib", "_w", "_buf", "_count", "_pose", "_poses", "_presolve_c"})


class World:
    """A world of rigid bodies (see the package docstring for the whole API)."""

    def __init__(self, *, gravity: Vec = (0.0, 0.0), tolerance: float = 1e-9,
                 cell_size: float = 0.0, rest_speed: float = 0.0, collapse_time: float = 0.0,
                 max_events: int = 0, contact_step: float = CONTACT_STEP) -> None:
        # every number checked before anything is made (scene files' rules: limits.py)
        gravity = _vector("gravity", gravity)
        tolerance = _number("tolerance", tolerance, positive=True)
        cell_size = _number("cell_size", cell_size)
        rest_speed = _number("rest_speed", rest_speed)
        collapse_time = _number("collapse_time", collapse_time)
        contact_step = _number("contact_step", contact_step, nonneg=True)
        if (isinstance(max_events, bool) or not isinstance(max_events, numbers.Integral)
                or not 0 <= max_events <= limits.MAX_EVENTS):
            raise EngineError(f"max_events: a whole number of events from 0 (no limit) to "
                              f"{limits.MAX_EVENTS}, not {limits.shown(max_events)}")
        self._ffi, self._lib = load()
        cfg = self._ffi.new("m2c_config *")
        cfg.tolerance = tolerance
        cfg.cell_size = cell_size
        cfg.rest_speed = rest_speed
        cfg.collapse_time = collapse_time
        cfg.max_events = int(max_events)
        cfg.contact_step = contact_step
        ptr = self._lib.m2c_world_new(cfg)
        if ptr == self._ffi.NULL:
            raise MemoryError("m2c_world_new")
        self._attach(ptr)
        self.gravity = gravity
        self.tolerance = tolerance
        # the contact solver's step h (0: off): its ticks are at the multiples of h, and a
        # server models a held body's hop from it (max2code/server/room.py)
        self.contact_step = float(contact_step)
        self.bodies: list[BodyInfo] = []
        self._names: dict[str, int] = {}
        self._groups: dict[str, int] = {}
        self._handlers = Handlers()
        self._flag_key: object = None
        self._failure: BaseException | None = None
        self._timers: dict[int, _Timer] = {}
        self._density: list[float] = []
        self._gravity: list[Vec] = []
        self._dormant: dict[int, tuple[float, float]] = {}
        self._input_callbacks: list[Callable[["World", Event], None]] = []
        self.inputs: list[Input] = []   # the inputs that happened, in order (write_script)

    def _attach(self, ptr) -> None:
        """Own the core's world `ptr` (new or loaded from a snapshot): buffers and callback."""
        self._w = self._ffi.gc(ptr, self._lib.m2c_world_free)
        self._presolve_c = self._ffi.callback("int(void *, const m2c_event *)", self._presolve,
                                              onerror=self._presolve_error)
        self._lib.m2c_world_set_presolve(self._w, self._presolve_c, self._ffi.NULL)
        self._buf = self._ffi.new("m2c_event[]", BUFFER)
        self._count = self._ffi.new("int *")
        self._pose = self._ffi.new("double[3]")
        self._poses = self._ffi.new("double[]", 0)

    # -- snapshots: pickle, copy.deepcopy, restore ----------------------------------------------

    def _core_bytes(self) -> bytes:
        """The core's whole state (m2c_world_save)."""
        n = self._lib.m2c_world_save(self._w, self._ffi.NULL, 0)
        buf = self._ffi.new("char[]", n)
        self._lib.m2c_world_save(self._w, buf, n)
        return bytes(self._ffi.buffer(buf, n))

    def __getstate__(self) -> dict:
        """For pickle and copy.deepcopy: the core's state as bytes, the rest as it is
        (callbacks included: pickle needs them to be picklable, module-level functions)."""
        state = {k: v for k, v in self.__dict__.items() if k not in _NATIVE}
        state["_core"] = self._core_bytes()
        return state

    def __setstate__(self, state: dict) -> None:
        state = dict(state)
        core = state.pop("_core")
        self.__dict__.update(state)
        self._ffi, self._lib = load()
        ptr = self._lib.m2c_world_load(core, len(core))
        if ptr == self._ffi.NULL:
            raise EngineError("restore: the snapshot is not this engine build's, or damaged")
        self._attach(ptr)

    def restore(self, snapshot: "World") -> None:
        """Put this world back into the state of `snapshot` (a copy.deepcopy of a World taken
        earlier: rollback); the snapshot stays usable."""
        import copy
        self.__dict__.clear()
        self.__setstate__(copy.deepcopy(snapshot.__getstate__()))

    def _span(self, shapes: list[tuple[list[Vec], float]], pose: tuple[float, float, float],
              name: str = "position") -> None:
        """A body placed at `pose` reaches no farther from the origin than 2^45 tolerances
        (limits.span_problem: farther, its coordinates round by more than the contact slack)."""
        reach = max((max(abs(x), abs(y)) + r for v, r in shapes for x, y in transform(v, pose)),
                    default=0.0)
        problem = limits.span_problem(reach, self.tolerance)
        if problem:
            raise EngineError(f"{name}: the body {problem}")

    # -- building ---------------------------------------------------------------------------

    def add_body(self, vertices: Sequence[Vec] = (), *, radius: float = 0.0, kind: str = "dynamic",
                 position: Vec = (0.0, 0.0), angle: float = 0.0, velocity: Vec = (0.0, 0.0),
                 omega: float = 0.0, gravity: Vec | None = None, mass: float | None = None,
                 density: float = 1.0, inertia: float | None = None, restitution: float = 1.0,
                 group: str | None = None, name: str | None = None,
                 color: str | None = None, friction: float = 0.0, category: int = 1,
                 mask: int = 0xFFFFFFFF, data: object = None, collision_type: int = 0,
                 sensor: bool = False,
                 parts: Sequence[tuple[Sequence[Vec], float]] | None = None) -> int:
        """Add a body; returns its id. `vertices` are offsets from `position` in the body's
        frame (turned by `angle`): one vertex and a radius make a circle, two a segment (a
        capsule with a radius), three or more a convex polygon, in either winding (kept
        anticlockwise). A dynamic body's reference point moves to its centre of mass (and its
        vertices with it: see `bodies`). `gravity` overrides the world's for this body (static
        bodies have none). `friction` is a Coulomb coefficient, at impacts only (a contact uses
        sqrt(fa fb); README). A pair collides when neither `group` is shared and each body's
        `category` bits meet the other's `mask`. `data` is yours (`bodies[id].data`, and
        every event's `data`). `collision_type` selects collision handlers; a `sensor` never
        responds: it reports a body starting to overlap it ("sensor") and, once per such
        event, the two stopping to overlap ("sensor_leave"), each at its exact time.
        `parts` (with `vertices` empty and no radius) makes a compound body: see
        add_compound."""
        if kind not in KINDS:
            raise EngineError(f"kind must be one of {', '.join(KINDS)}, not {kind!r}")
        if parts is not None:
            if len(vertices) or radius:
                raise EngineError("a compound body's shape is its parts: give no vertices or radius")
            if not len(parts):
                raise EngineError("a compound body needs at least one part")
            shapes = _parts(parts)
        else:
            shapes = [_shape("", vertices, radius)]
        _mask("category", category)
        _mask("mask", mask)
        # every number checked before anything changes (scene files' rules: limits.py)
        px, py = _vector("position", position, _now_number)
        angle = _now_number("angle", angle)
        vx, vy = _vector("velocity", velocity, _now_number)
        omega = _now_number("omega", omega)
        own = self.gravity if gravity is None else _vector("gravity", gravity, _now_number)
        mass = None if mass is None else _number("mass", mass, positive=True)
        density = _number("density", density, positive=True)
        inertia = None if inertia is None else _number("inertia", inertia, positive=True)
        restitution = _number("restitution", restitution, lo=0.0, hi=1.0)
        friction = _number("friction", friction, nonneg=True)
        self._span(shapes, (px, py, angle))
        m = I = 0.0
        if kind == "dynamic":
            props = _shape_mass(shapes, parts is not None)
            cx, cy = props.centroid
            if cx or cy:
                shapes = [([(x - cx, y - cy) for x, y in v], r) for v, r in shapes]
                c, s = math.cos(angle), math.sin(angle)
                px, py = px + c * cx - s * cy, py + s * cx + c * cy
            m = mass if mass is not None else density * props.area
            I = inertia if inertia is not None else m * props.inertia_per_mass
            if not (m > 0):
                raise EngineError("a dynamic body needs a positive mass (give mass=, or an area)")
            if not (I > 0):  # a point mass (a segment's rod with no length cannot happen)
                I = m * 1e-12
            _mass_range("mass" if mass is not None else "density", m, I, mass is None,
                        "inertia" if inertia is not None else "the shape")
        g = own  # own: what it falls with when dynamic (set_kind)
        if kind == "static":
            g = (0.0, 0.0)
        if kind == "kinematic" and gravity is None:
            g = (0.0, 0.0)
        gid = -1 if group is None else self._groups.get(group, len(self._groups))
        d = self._ffi.new("m2c_body_def *", self._lib.m2c_default_body_def())
        flats = [self._ffi.new("double[]", [c for p in v for c in p]) for v, _ in shapes]
        d.kind = KINDS[kind]
        d.x, d.y, d.angle = px, py, angle
        d.vx, d.vy, d.omega = vx, vy, omega
        d.ax, d.ay = g
        d.mass, d.inertia = m, I
        d.restitution = float(restitution)
        d.friction = float(friction)
        if parts is None:
            d.radius = shapes[0][1]
            d.nvertices = len(shapes[0][0])
            d.vertices = flats[0]
        else:
            cparts = self._ffi.new("m2c_part[]", len(shapes))
            for k, ((v, r), flat) in enumerate(zip(shapes, flats)):
                cparts[k].nvertices = len(v)
                cparts[k].vertices = flat
                cparts[k].radius = r
            d.nparts = len(shapes)
            d.parts = cparts
        d.group = gid
        d.category, d.mask = category, mask
        d.flags = (FLAG_SENSOR if sensor else 0) | self._handlers.flags_for(len(self.bodies), collision_type)
        i = self._lib.m2c_world_add_body(self._w, d)
        if i < 0:
            raise EngineError(self.error())
        if group is not None:
            self._groups.setdefault(group, gid)
        name = name if name is not None else f"body{i}"
        verts = tuple(p for v, _ in shapes for p in v)
        compound = tuple((tuple(v), r) for v, r in shapes) if parts is not None else ()
        self.bodies.append(BodyInfo(i, name, kind, verts, shapes[0][1] if parts is None else 0.0,
                                    m if kind == "dynamic" else math.inf,
                                    I if kind == "dynamic" else math.inf,
                                    float(restitution), group, color, float(friction),
                                    category, mask, data, True, int(collision_type), bool(sensor),
                                    compound))
        self._names[name] = i
        self._density.append(float(density))
        self._gravity.append(own)
        return i

    def add_circle(self, position: Vec, radius: float, **kw) -> int:
        return self.add_body([(0.0, 0.0)], radius=radius, position=position, **kw)

    def add_segment(self, a: Vec, b: Vec, *, radius: float = 0.0, kind: str = "static", **kw) -> int:
        return self.add_body([a, b], radius=radius, kind=kind, **kw)

    def add_polygon(self, vertices: Sequence[Vec], **kw) -> int:
        return self.add_body(vertices, **kw)

    def add_compound(self, parts: Sequence[tuple[Sequence[Vec], float]], **kw) -> int:
        """A compound body: several convex shapes on one rigid body, each (vertices, radius)
        in the body's frame as add_body's shape ((centre,), r) a circle, (a, b) with r a
        capsule, three or more vertices a polygon). It moves, turns and responds as one body;
        a contact is its parts' earliest. Mass, centre of mass and inertia come from the parts
        (one `density`; the parallel axis theorem) unless `mass`/`inertia` are given; the
        reference point moves to the centre of mass (`bodies[id].parts` follow). The other
        keywords are add_body's."""
        return self.add_body((), parts=parts, **kw)

    def body(self, name_or_id: str | int) -> BodyInfo:
        i = self._names[name_or_id] if isinstance(name_or_id, str) else name_or_id
        return self.bodies[i]

    # -- running ----------------------------------------------------------------------------

    @property
    def time(self) -> float:
        return float(self._lib.m2c_world_time(self._w))

    def on_collision(self, callback: Callable[["World", Event], None], body: int | None = None) -> None:
        """callback(world, event) for every reported event (collision, sensor, sensor_leave,
        rest, wake, separate), or only those of `body`, in order, at the event's time (the world's time is
        then the event's; the callback may change the world: remove, set_velocity, ...)."""
        if body is None:
            self._handlers.every.append(callback)
        else:
            self._handlers.per_body.setdefault(body, []).append(callback)

    def on_collision_with(self, a: int, b: int, callback: Callable[["World", Event], None]) -> None:
        """callback(world, event) for the events between bodies a and b (PGE's
        on_collision_with)."""
        self._handlers.per_pair.setdefault((min(a, b), max(a, b)), []).append(callback)

    def on_pre_solve(self, body: int, callback: Callable[["World", Event], object]) -> None:
        """callback(world, event) before the response to each contact of `body` (kind
        "presolve": normal, point and closing speed; no impulse yet). Returning False vetoes it:
        the pair passes through each other until they next meet (one-way platforms). It may
        read the world, not change it."""
        self._handlers.pre_solve_body.setdefault(body, []).append(callback)

    def collision_handler(self, a: int, b: int | None = None) -> CollisionHandler:
        """pymunk's handler for collision types a and b (b None: a with anything): set its
        begin, pre_solve, post_solve and separate (see CollisionHandler)."""
        for h in self._handlers.typed:
            if (h.a, h.b) in ((a, b), (b, a)):
                return h
        h = CollisionHandler(a, b)
        self._handlers.typed.append(h)
        return h

    def _refresh_flags(self) -> None:
        """The core's per-body flags for the handlers (pre-solve, separate), when they changed."""
        hs = self._handlers
        key = (tuple((h.a, h.b, bool(h.begin or h.pre_solve), bool(h.separate)) for h in hs.typed),
               tuple(sorted(hs.pre_solve_body)), len(self.bodies))
        if key == self._flag_key:
            return
        self._flag_key = key
        for info in self.bodies:
            if info.alive:
                flags = (FLAG_SENSOR if info.sensor else 0) | hs.flags_for(info.id, info.collision_type)
                self._call(self._lib.m2c_world_set_flags(self._w, info.id, flags))

    def _event(self, e) -> Event:
        data = (self.bodies[e.a].data if 0 <= e.a < len(self.bodies) and e.kind != 4 else None,
                self.bodies[e.b].data if 0 <= e.b < len(self.bodies) else None)
        kind = EVENT_KINDS.get(e.kind, str(e.kind))
        if e.kind == 4:
            timer = self._timers.get(e.a)
            data = (timer.data if timer else None, None)
            if timer and timer.is_input:
                kind = "input"
        return Event(e.time, kind, e.a, e.b, (e.nx, e.ny),
                     (e.px, e.py), e.speed, e.impulse, data)

    def _types(self, ev: Event) -> tuple[int, int]:
        return (self.bodies[ev.a].collision_type, self.bodies[ev.b].collision_type)

    def _presolve(self, user, e) -> int:
        """The core's pre-solve callback (through cffi): 1 keeps the contact, 0 vetoes it."""
        if self._failure is not None:
            return 1
        ev = self._event(e)
        return 1 if self._handlers.pre_solve(self, ev, self._types(ev)) else 0

    def _presolve_error(self, exc_type, exc, tb) -> int:
        self._failure = exc  # raised by step_to once the core returns
        return 1

    def add_timer(self, t: float, callback: Callable[["World", Event], None] | None = None,
                  data: object = None) -> int:
        """A timer event at time t (reported, and passed to callback(world, event); the event's
        data is (data, None)); returns its id, for cancel_timer."""
        k = self._lib.m2c_world_add_timer(self._w, _number("t", t))
        if k < 0:
            raise EngineError(self.error())
        self._timers[k] = _Timer(callback, data)
        return k

    def add_input(self, event: Input) -> int:
        """Queue an input event (a key, the mouse) at its time (>= now): an "input" event then,
        its data (event, None), passed to the on_input callbacks. Equal times keep the order
        they were queued in: the same timed input gives the same run, live or from a script."""
        k = self._lib.m2c_world_add_timer(self._w, _number("event.time", event.time))
        if k < 0:
            raise EngineError(self.error())
        self._timers[k] = _Timer(None, event, True)
        return k

    def on_input(self, callback: Callable[["World", Event], None]) -> None:
        """callback(world, event) for every input event at its time (event.data[0]: Input)."""
        self._input_callbacks.append(callback)

    def cancel_timer(self, timer: int) -> None:
        """Cancel a pending timer (PGE's at_cancel): an EngineError when it already fired or
        was cancelled."""
        self._call(self._lib.m2c_world_cancel_timer(self._w, timer))
        self._timers.pop(timer, None)

    def step_to(self, t: float, events: bool = True) -> list[Event]:
        """Process every event up to time t (inclusive); returns the reported events (none with
        events=False, which saves making Python objects of them: callbacks still run)."""
        return list(self._run(_number("t", t), events))

    def stream_to(self, t: float) -> Iterator[Event]:
        """step_to(t) as a stream: each reported event as the core hands it out, so memory
        stays bounded however many there are (`max2code sim` writes its log this way). The
        world is stepped as far as the stream has been read."""
        return self._run(_number("t", t), True)

    def _run(self, t: float, events: bool) -> Iterator[Event]:
        # with callbacks the core stops after each reported event, so that a callback sees the
        # world at its event's time (and may change it: set_velocity, add_timer)
        listening = self._handlers.any()
        self._refresh_flags()
        room = 4 if listening or any(tm.callback or tm.is_input for tm in self._timers.values()) else BUFFER
        while True:
            # (a call returns after a bounded amount of work, events or not: signals are
            # honoured between calls)
            status = self._lib.m2c_world_step(self._w, float(t), self._buf, room, self._count)
            if self._failure is not None:
                failure, self._failure = self._failure, None
                raise failure
            if status < 0:
                raise EngineError(self.error())
            if not events and not listening and not self._timers:
                if status == 0:
                    return
                continue
            for k in range(self._count[0]):
                ev = self._event(self._buf[k])
                self._dispatch(ev)
                if events:
                    yield ev
            if status == 0:
                return

    def _dispatch(self, ev: Event) -> None:
        if ev.kind == "input":
            self._timers.pop(ev.a, None)
            self.inputs.append(ev.data[0])
            for cb in list(self._input_callbacks):
                cb(self, ev)
            return
        if ev.kind == "timer":
            timer = self._timers.pop(ev.a, None)
            if timer and timer.callback:
                timer.callback(self, ev)
            return
        self._handlers.dispatch(self, ev, self._types(ev) if ev.b >= 0 else (0, 0))

    # -- changing bodies now (also from callbacks; effective at once for prediction) ---------

    def _call(self, status: int) -> None:
        if status < 0:
            raise EngineError(self.error())

    def set_velocity(self, body: int, velocity: Vec, omega: float = 0.0) -> None:
        """Change a dynamic or kinematic body's velocity now (an input event: steering a
        kinematic paddle predicts every dynamic body against its new path at once)."""
        vx, vy = _vector("velocity", velocity, _now_number)
        self._call(self._lib.m2c_world_set_velocity(self._w, body, vx, vy,
                                                    _now_number("omega", omega)))

    def remove(self, body: int) -> None:
        """Remove a body now, also from inside a callback: nothing collides with it from now
        on (its id is never reused; `bodies[id].alive` turns False, its pose stays put)."""
        self._call(self._lib.m2c_world_remove_body(self._w, body))
        self.bodies[body] = replace(self.bodies[body], alive=False)

    def alive(self, body: int) -> bool:
        return bool(self._lib.m2c_world_body_alive(self._w, body))

    def set_pose(self, body: int, position: Vec, angle: float | None = None) -> None:
        """Move a body (any kind) to `position` (its reference point: a dynamic body's centre
        of mass) and `angle` (default: unchanged) now. An overlap with a body it can collide
        with at the new place is an EngineError naming that body, and nothing moves."""
        x, y = _vector("position", position, _now_number)
        a = self.pose(body)[2] if angle is None else _now_number("angle", angle)
        self._span([(list(v), r) for v, r in self.bodies[body].shapes], (x, y, a))
        self._call(self._lib.m2c_world_set_pose(self._w, body, x, y, a))

    def set_acceleration(self, body: int, acceleration: Vec) -> None:
        """The body's own constant acceleration (its gravity; PGE's put_xaccel/put_yaccel)."""
        ax, ay = _vector("acceleration", acceleration, _now_number)
        self._call(self._lib.m2c_world_set_acceleration(self._w, body, ax, ay))
        self._gravity[body] = (ax, ay)

    def acceleration(self, body: int) -> Vec:
        """The body's own constant acceleration: what it moves with while dynamic (add_body's
        `gravity`, else the world's; set_acceleration's). A static body, and a kinematic one
        given no gravity, keep it for set_kind and move without it meanwhile; a server reads
        it to tell a platformer's walker (it falls) from a top-down one."""
        return self._gravity[body]

    def set_mass(self, body: int, mass: float, inertia: float | None = None) -> None:
        """A new mass (and moment of inertia about the centre of mass: default the shape's, or
        the old one scaled with the mass). A static or kinematic body keeps them for when it
        becomes dynamic (set_kind)."""
        info = self.bodies[body]
        mass = _number("mass", mass, positive=True)
        given = inertia is not None
        if inertia is None:
            inertia = (info.inertia * mass / info.mass if math.isfinite(info.mass)
                       else mass * info.mass_properties().inertia_per_mass)
        else:
            inertia = _number("inertia", inertia, positive=True)
        if not (inertia > 0):
            inertia = mass * 1e-12  # a point mass
        _mass_range("mass", mass, inertia, False, "inertia" if given else "mass")
        if info.kind != "dynamic":
            self._dormant[body] = (float(mass), float(inertia))
            return
        self._call(self._lib.m2c_world_set_mass(self._w, body, float(mass), float(inertia), 0.0, 0.0))
        self._sync(body, mass=float(mass), inertia=float(inertia))

    def set_kind(self, body: int, kind: str) -> None:
        """Make a body static, kinematic or dynamic now (PGE's fix/unfix). A body becoming
        dynamic gets the mass given to set_mass, else its density (at add_body) times its area,
        and its reference point moves to its centre of mass (`bodies[id].vertices` follow);
        a body becoming static stops."""
        if kind not in KINDS:
            raise EngineError(f"kind must be one of {', '.join(KINDS)}, not {kind!r}")
        info = self.bodies[body]
        if not info.alive:
            raise EngineError("set_kind: the body was removed")
        if kind == info.kind:
            return
        if kind == "dynamic":
            props = info.mass_properties()
            m, I = self._dormant.get(body, (self._density[body] * props.area, 0.0))
            I = I or m * props.inertia_per_mass or m * 1e-12
            if not (m > 0):
                raise EngineError("set_kind: a dynamic body needs a positive mass (set_mass first)")
            _mass_range("set_kind", m, I, body not in self._dormant, "set_kind")
            cx, cy = props.centroid if props.area > 0 else (0.0, 0.0)
            self._call(self._lib.m2c_world_set_mass(self._w, body, m, I, cx, cy))
            self._call(self._lib.m2c_world_set_kind(self._w, body, KINDS[kind]))
            self._sync(body, kind=kind, mass=m, inertia=I)
            self.set_acceleration(body, self._gravity[body])
            return
        if info.kind == "dynamic":
            self._dormant[body] = (info.mass, info.inertia)
        self._call(self._lib.m2c_world_set_kind(self._w, body, KINDS[kind]))
        self._sync(body, kind=kind, mass=math.inf, inertia=math.inf)

    def apply_impulse(self, body: int, impulse: Vec, point: Vec | None = None) -> None:
        """Apply an impulse to a dynamic body now, at a world point (default: its centre of
        mass, which gives no spin)."""
        jx, jy = _vector("impulse", impulse, _now_number)
        x, y = self.pose(body)[:2] if point is None else _vector("point", point, _now_number)
        self._call(self._lib.m2c_world_apply_impulse(self._w, body, jx, jy, x, y))

    def _sync(self, body: int, **changes) -> None:
        """BodyInfo after a change: the core's vertices (set_mass may move the reference
        point to the centre of mass) and the changed fields."""
        info = self.bodies[body]
        n = len(info.vertices)
        out = self._ffi.new("double[]", 2 * n)
        self._lib.m2c_world_vertices(self._w, body, out, n)
        verts = tuple((out[2 * k], out[2 * k + 1]) for k in range(n))
        parts, at = [], 0
        for v, r in info.parts:
            parts.append((verts[at:at + len(v)], r))
            at += len(v)
        self.bodies[body] = replace(info, vertices=verts, parts=tuple(parts), **changes)

    # -- reading ----------------------------------------------------------------------------

    def pose(self, body: int, t: float | None = None) -> tuple[float, float, float]:
        """(x, y, angle) of the body's reference point at time t (default: now), exactly."""
        if self._lib.m2c_world_pose(self._w, body, self.time if t is None else _number("t", t),
                                    self._pose) < 0:
            raise EngineError(f"pose of body {body} at {t}: no such body, or before its last event")
        return (self._pose[0], self._pose[1], self._pose[2])

    def velocity(self, body: int, t: float | None = None) -> tuple[float, float, float]:
        """(vx, vy, omega) at time t (default: now)."""
        if self._lib.m2c_world_velocity(self._w, body, self.time if t is None else _number("t", t),
                                        self._pose) < 0:
            raise EngineError(f"velocity of body {body} at {t}: no such body, or before its last event")
        return (self._pose[0], self._pose[1], self._pose[2])

    def poses(self, t: float | None = None) -> list[tuple[float, float, float]]:
        """Every body's pose at time t (default: now): what a frame draws. One call into the
        core fills a flat buffer, copied out in bulk (no per-body crossing of the binding)."""
        flat = self._fill_poses(t)
        it = iter(memoryview(self._ffi.buffer(flat)).cast("d").tolist())
        return list(zip(it, it, it))

    def poses_array(self, t: float | None = None):
        """poses(t) as a numpy array of shape (N, 3), columns x, y, angle (a copy; needs numpy)."""
        import numpy as np
        flat = self._fill_poses(t)
        return np.frombuffer(self._ffi.buffer(flat), dtype=np.float64).reshape(-1, 3).copy()

    def _fill_poses(self, t: float | None):
        """The core's poses at t in a buffer of exactly 3 N doubles (kept between calls)."""
        n = len(self.bodies)
        if len(self._poses) != 3 * n:
            self._poses = self._ffi.new("double[]", 3 * n)
        if self._lib.m2c_world_poses(self._w, self.time if t is None else _number("t", t),
                                     self._poses) < 0:
            raise EngineError(f"poses at {t}: before some body's last event")
        return self._poses

    def motions(self) -> tuple[list[tuple[float, ...]], list[int]]:
        """Every body's motion segment as the core holds it, and its change counter:
        ([(t0, x, y, angle, vx, vy, omega, ax, ay), ...], [counter, ...]). The pose at t is
        (x, y) + (vx, vy) s + (ax, ay) s^2/2, angle + omega s with s = t - t0; a counter
        changes exactly when its body's motion does. What a remote client needs to draw any
        frame until the next event (max2code serve), in one call into the core."""
        n = len(self.bodies)
        flat = self._ffi.new("double[]", 9 * n)
        counters = self._ffi.new("unsigned int[]", n)
        self._lib.m2c_world_motions(self._w, flat, counters)
        it = iter(memoryview(self._ffi.buffer(flat)).cast("d").tolist())
        return list(zip(*[it] * 9)), list(counters)

    def next_time(self) -> float:
        """The earliest time anything is queued for (a contact, a timer, or an internal event
        such as a cell crossing): no reported event comes before it; inf when nothing is
        queued. A server sleeps until then (or until input arrives)."""
        return float(self._lib.m2c_world_next_time(self._w))

    # -- queries at any time >= now -----------------------------------------------------------

    def _ids(self, fill) -> list[int]:
        cap = max(16, len(self.bodies))
        out = self._ffi.new("int[]", cap)
        n = fill(out, cap)
        if n < 0:
            raise EngineError(self.error())
        return [out[k] for k in range(min(n, cap))]

    def query_point(self, point: Vec, t: float | None = None, mask: int = 0xFFFFFFFF) -> list[int]:
        """The bodies whose shape contains `point` at time t (default now), in id order;
        only those whose category meets `mask`."""
        at = self.time if t is None else _number("t", t)
        return self._ids(lambda out, cap: self._lib.m2c_world_query_point(
            self._w, at, *_vector("point", point), _mask("mask", mask), out, cap))

    def query_box(self, lower: Vec, upper: Vec, t: float | None = None,
                  mask: int = 0xFFFFFFFF) -> list[int]:
        """The bodies whose shape meets the axis-aligned box [lower, upper] at time t."""
        at = self.time if t is None else _number("t", t)
        return self._ids(lambda out, cap: self._lib.m2c_world_query_box(
            self._w, at, *_vector("lower", lower), *_vector("upper", upper), _mask("mask", mask),
            out, cap))

    def cast_ray(self, start: Vec, end: Vec, t: float | None = None,
                 mask: int = 0xFFFFFFFF) -> RayHit | None:
        """The first shape the segment start -> end enters at time t (exact: the smallest root
        of each feature's crossing), or None. A shape containing `start` is not hit."""
        at = self.time if t is None else _number("t", t)
        f, b, n = self._ffi.new("double *"), self._ffi.new("int *"), self._ffi.new("double[2]")
        start, end = _vector("start", start), _vector("end", end)
        r = self._lib.m2c_world_cast_ray(self._w, at, *start, *end, _mask("mask", mask), f, b, n)
        if r < 0:
            raise EngineError(self.error())
        if r == 0:
            return None
        x = start[0] + f[0] * (end[0] - start[0])
        y = start[1] + f[0] * (end[1] - start[1])
        return RayHit(b[0], (x, y), (n[0], n[1]), f[0])

    def first_contact(self, a: int, b: int, horizon: float) -> float | None:
        """When bodies a and b would first touch within `horizon` from now, were they alone
        and nothing changed (any kinds: kinematic orbits too); None when they would not."""
        t = self._ffi.new("double *")
        r = self._lib.m2c_world_first_contact(self._w, a, b, _number("horizon", horizon), t)
        if r < 0:
            raise EngineError(self.error())
        return t[0] if r == 1 else None

    def energy(self, t: float | None = None) -> float:
        """Kinetic plus potential energy (-m a.x) of the dynamic bodies."""
        return float(self._lib.m2c_world_energy(self._w, self.time if t is None else _number("t", t)))

    def asleep(self, body: int) -> bool:
        return bool(self._lib.m2c_world_asleep(self._w, body))

    def has_callbacks(self) -> bool:
        """True when stepping this world may run Python code of its owner's (collision,
        pre-solve, timer or input callbacks): a copy stepped ahead (max2code serve's forecast)
        would run that code twice, so such a world is never copied to look ahead."""
        h = self._handlers
        return bool(h.any() or h.pre_solve_body or self._input_callbacks
                    or any(tm.callback for tm in self._timers.values()))

    def solving(self, body: int) -> bool:
        """True while the body is in sustained contact, moved by the contact solver."""
        return bool(self._lib.m2c_world_solving(self._w, body))

    @property
    def contact_slop(self) -> float:
        """The overlap a pair held by the contact solver may keep (10,000 tolerances with the
        solver on, else 0): within it such a pair is no event, beyond it an exact one."""
        return float(self._lib.m2c_world_contact_slop(self._w))

    def certificate(self, body: int) -> tuple[bool, float]:
        """The sleep certificate of an asleep body's island, checked now: (found, residual),
        residual = the worst unbalanced force per weight under the best contact forces found
        (non-negative, inside the friction cones). Raises for a body that is not asleep."""
        r = self._ffi.new("double *")
        ok = self._lib.m2c_world_certificate(self._w, body, r)
        if ok < 0:
            raise EngineError(f"certificate: body {body} is not asleep")
        return bool(ok), float(r[0])

    def stats(self) -> dict[str, object]:
        s = self._ffi.new("m2c_stats *")
        self._lib.m2c_world_stats(self._w, s)
        out: dict[str, object] = {}
        for name in ("events", "collisions", "cell_crossings", "windows", "windows_solved", "stale",
                     "predictions", "pair_tests", "solves", "rests", "wakes", "ncells_x", "ncells_y",
                     "cell_size", "solver_ticks", "solver_iterations", "certificates"):
            out[name] = getattr(s, name)
        out["solves_by_degree"] = {d: s.solves_by_degree[d] for d in range(17) if s.solves_by_degree[d]}
        return out

    def error(self) -> str:
        return self._ffi.string(self._lib.m2c_world_error(self._w)).decode(errors="replace")

    def names(self) -> Iterable[str]:
        return (b.name for b in self.bodies)
