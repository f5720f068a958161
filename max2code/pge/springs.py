"""PGE's springs on the predictive engine: contacts of spring-driven bodies still predicted,
never frame-checked (docs/engine-springs.md has the design and its proof).

Time advances in windows. At a window's start every sprung body has its exact state (the ODE's,
max2code.pge.spring_model); over the window it moves in the engine on its degree-2 Taylor
polynomial (its velocity and acceleration now), and `spring_model.window_bounds` proves how far
the real motion can stray from that polynomial: delta_i(tau) = J_i tau^3 / 6. A twin sensor of
the body, its shape grown by delta_i(h), rides the same polynomial, so it contains the real body
throughout the window: while the sensor touches nothing no contact can happen, and the window
ends when the world's next event (a frame, a timer) is due. A sensor contact ends the window
early, at the model's root: the body is put at its exact state there and the next window, sized
so that delta is at most a quarter of the body's gap, is tighter; gaps halve from window to
window until the gap is within the contact tolerance, where the body moves in the engine on its
polynomial with delta <= that tolerance and the engine itself predicts and answers the contact
(its impulse is added to the exact velocity). The exact state at a window's end comes from a
high-order integrator (scipy's DOP853 at rtol 1e-12), not from the polynomial, and spring
events (mid, end, when) are roots of the integrator's dense output, refined by it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Callable

import numpy as np

from .spring_model import Link, System, window_for
from .gaps import gap, placed
from .signals import Rebuild, WindowEnd

if TYPE_CHECKING:
    from .physics import Physics

DELTA_FAR = 0.01        # a window's largest proven deviation (PGE's unit square)
DELTA_CONTACT = 1e-9    # ... near a contact: the contact tolerance (physics.TOLERANCE)
CONTACT_GAP = 4 * DELTA_CONTACT
RTOL, ATOL = 1e-12, 1e-15
H_MAX = 0.05            # no window longer (s): frames end them sooner anyway
DEAD_SENSORS = 200      # rebuild the world after this many removed twin sensors
EPS_T = 1e-12           # an event this close after a window's start is the one that ended the last
STUCK = 2000            # windows within 1e-6 (1 + |t|) s of one time: a Zeno series, an error


def _error(message: str) -> Exception:
    from .physics import PgeError
    return PgeError(message)


def _checked(c, call: str):
    from .objects import Colour
    if not isinstance(c, Colour):
        raise _error(f"{call}: expected a colour (pge.rgb), not {type(c).__name__}")
    return c


def make(physics: "Physics", a, b, k, d, l, name: str) -> Spring:
    """PGE's spring(ob1, ob2, k, d, l): between two level-0 objects' centres of mass; without
    l (or l < 0, as PGE's engine takes it) the spring rests at their distance now."""
    for o, which in ((a, "first"), (b, "second")):
        if isinstance(o, Spring) or not hasattr(o, "state") or not hasattr(o, "fixed"):
            raise _error(f"spring: the {which} object must be a level-0 box, polygon or circle")
        if o.removed:
            raise _error(f"spring: the {which} object, {o.name}, has been deleted (rm)")
    if a is b:
        raise _error("spring: both ends are the same object")
    vals = {}
    for key, v in (("k", k), ("damping", d)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0):
            raise _error(f"spring: {key} must be a number >= 0, not {v!r}")
        vals[key] = float(v)
    if l is None or (isinstance(l, (int, float)) and l < 0):
        pa, pb = physics.pose(a), physics.pose(b)
        l = math.hypot(pb[0] - pa[0], pb[1] - pa[1])
    if not (isinstance(l, (int, float)) and math.isfinite(l)):
        raise _error(f"spring: the rest length must be a number, not {l!r}")
    physics.touch()
    s = Spring(a, b, vals["k"], vals["damping"], float(l), name, physics=physics)
    physics.springs.springs.append(s)
    return s


@dataclass
class Spring:
    """One spring between two level-0 objects: rest length `l0`, stiffness `k`, damping `d`;
    drawing (`draw`), debug colours at the rest length (`mid`) and at the turning points
    (`end`), and `when` callbacks at given lengths."""
    a: object
    b: object
    k: float
    d: float
    l0: float
    name: str
    colour: object = None
    width: float = 0.0
    end_colour: object = None
    mid_colour: object = None
    whens: list = field(default_factory=list)   # (length, callback)
    removed: bool = False
    physics: object = None

    # -- PGE's spring methods (each returns the spring, for chaining) ----------------------

    def draw(self, c, w: float) -> "Spring":
        """Drawn as a line of width w (unit-square lengths) in colour c, under the objects."""
        self.colour, self.width = _checked(c, "draw"), float(w)
        return self

    def end(self, c) -> "Spring":
        """At each turning point (the length's rate of change 0: the ends rest relative to each
        other), the objects are drawn in colour c in the next frame."""
        self.end_colour = _checked(c, "end")
        return self

    def mid(self, c) -> "Spring":
        """Each time the spring passes its rest length, the objects are drawn in colour c in
        the next frame."""
        self.mid_colour = _checked(c, "mid")
        return self

    def when(self, l: float, p: Callable) -> "Spring":
        """Call p(spring, event) at the exact time the spring's length reaches l."""
        if not (isinstance(l, (int, float)) and math.isfinite(l) and l >= 0):
            raise _error(f"when: expected a length >= 0, not {l!r}")
        self.whens.append((float(l), p))
        return self

    def rm(self) -> None:
        if not self.removed:
            self.removed = True
            if self.physics is not None:
                self.physics.touch()

    def __getattr__(self, name: str):
        if name.startswith("_"):
            raise AttributeError(name)
        raise _error(f"{name}: {self.name} is a spring (it has draw, end, mid, when and rm)")

    def alive(self) -> bool:
        return not (self.removed or self.a.removed or self.b.removed)

    def moving(self) -> bool:
        return any(not o.fixed for o in (self.a, self.b))


@dataclass
class Window:
    """One window: where it started, its polynomial models, the integrator's solution."""
    t0: float
    end: float
    ids: list[int]
    y0: np.ndarray
    a0: np.ndarray
    omega: list[float]
    sol: object
    events: list      # (spring, what, length, callback) per solve_ivp event function
    sensors: set[int]
    target: float     # the world time the window steps to


class Springs:
    """The springs of a game and the windows that advance its sprung bodies."""

    def __init__(self) -> None:
        self.springs: list[Spring] = []
        self.window: Window | None = None
        self.dead = 0
        self.windows = 0
        self._since = (-math.inf, 0)   # (a time, windows since it)
        self.on_event: Callable[[Spring, str, float, float, Callable | None], None] | None = None

    def live(self) -> list[Spring]:
        self.springs = [s for s in self.springs if s.alive()]
        return self.springs

    def sprung(self) -> list:
        """The moving objects springs pull (in a stable order)."""
        out: list = []
        for s in self.live():
            for o in (s.a, s.b):
                if not o.fixed and o not in out:
                    out.append(o)
        return out

    def active(self) -> bool:
        return any(s.moving() for s in self.live())

    def in_window(self, body: int) -> bool:
        return self.window is not None and body in self.window.ids

    def is_sensor(self, body: int) -> bool:
        return self.window is not None and body in self.window.sensors

    # -- stepping ---------------------------------------------------------------------------

    def advance(self, phys: "Physics", t: float) -> None:
        """Windows until game time t (phys raises its Rebuild when a change made it stale)."""
        while phys.world.time < t - phys.t0:
            if phys.stale:
                raise Rebuild()
            self._window(phys, t - phys.t0)
            self._check_progress(phys.now)
        if phys.stale:
            raise Rebuild()

    def _check_progress(self, now: float) -> None:
        """A body pressed on something by its spring bounces in ever shorter series (docs:
        not modelled): an error naming it rather than a hang."""
        since, count = self._since
        if now - since > 1e-6 * (1 + abs(now)):
            self._since = (now, 0)
        elif count + 1 > STUCK:
            raise _error(f"stuck: {STUCK} spring windows within 1e-6 s of t = {since:.9g} (a body "
                         "pressed against something by a spring: sustained contact under a "
                         "spring is not modelled)")
        else:
            self._since = (since, count + 1)

    def _system(self, phys: "Physics", bodies: list) -> System:
        index = {id(o): i for i, o in enumerate(bodies)}
        links = []
        for s in self.live():
            ia, ib = index.get(id(s.a)), index.get(id(s.b))
            if ia is None and ib is None:
                continue
            links.append(Link(ia, ib, s.k, s.d, s.l0, tuple(phys.pose(s.a)[:2]), tuple(phys.pose(s.b)[:2])))
        g = tuple((phys.gravity[0] + o.acc[0], phys.gravity[1] + o.acc[1]) for o in bodies)
        return System(tuple(float(o.kg) for o in bodies), g, tuple(links))

    def _gaps(self, phys: "Physics", bodies: list) -> list[float]:
        w = phys.world
        poses = w.poses()
        mine = {o.body for o in bodies}
        shapes = {}
        for info in w.bodies:
            if info.alive and not info.sensor:
                shapes[info.id] = (placed(info.vertices, poses[info.id]), info.radius)
        out = []
        for o in bodies:
            pa, ra = shapes[o.body]
            out.append(min((gap(pa, ra, pb, rb) for j, (pb, rb) in shapes.items()
                            if j != o.body), default=math.inf))
        del mine
        return out

    def _events(self, system: System, bodies: list) -> list:
        """solve_ivp event functions: for each spring its rest length (mid), turning points
        (end) and `when` lengths; returns [(function, (spring, what, length, callback))]."""
        out = []
        n = system.n
        live = [s for s in self.live()]
        k = 0
        for s in live:
            if not s.moving():
                continue
            link = system.links[k]
            k += 1

            def length(t, y, link=link):
                pos, vel = y[:2 * n].reshape(n, 2), y[2 * n:].reshape(n, 2)
                return system.tension(link, pos, vel)[1:]

            out.append((lambda t, y, L=length, l0=s.l0: L(t, y)[0] - l0, (s, "mid", s.l0, None)))
            out.append((lambda t, y, L=length: L(t, y)[1], (s, "end", None, None)))
            for lw, p in s.whens:
                out.append((lambda t, y, L=length, lw=lw: L(t, y)[0] - lw, (s, "when", lw, p)))
        return out

    def _window(self, phys: "Physics", t_local: float) -> None:
        try:
            from scipy.integrate import solve_ivp
        except ImportError:
            raise _error("spring: springs need scipy (pip install 'max2code[springs]')") from None

        from ..engine.world import EngineError
        w = phys.world
        bodies = self.sprung()
        system = self._system(phys, bodies)
        n = system.n
        ids = [o.body for o in bodies]
        t0 = w.time
        vel3 = [w.velocity(i) for i in ids]
        pos = np.array([w.pose(i)[:2] for i in ids], dtype=float).reshape(n, 2)
        vel = np.array([v[:2] for v in vel3], dtype=float).reshape(n, 2)
        y0 = np.concatenate([pos.ravel(), vel.ravel()])
        gaps = self._gaps(phys, bodies)
        near = [g <= CONTACT_GAP for g in gaps]
        budget = [DELTA_CONTACT if near[i] else min(DELTA_FAR, gaps[i] / 4) for i in range(n)]
        h_cap = min(H_MAX, t_local - t0)
        h, bounds = window_for(system, y0, budget, h_cap)
        events = self._events(system, bodies)
        fns = [f for f, _ in events]  # (not terminal: a root at the start is the last one's)
        sol = solve_ivp(system.rhs, (0.0, h), y0, method="DOP853", rtol=RTOL, atol=ATOL,
                        dense_output=True, events=fns or None)
        end = h
        for k, (_, (s, what, _, _)) in enumerate(events):
            if what == "when":
                times = [te for te in sol.t_events[k] if te > EPS_T]
                if times:
                    end = min(end, times[0])
        a0 = system.accelerations(pos, vel)
        sensors: set[int] = set()
        for i, o in enumerate(bodies):
            w.set_velocity(ids[i], tuple(vel[i]), vel3[i][2])
            w.set_acceleration(ids[i], tuple(a0[i]))
            if near[i]:
                continue
            info = w.bodies[ids[i]]
            sensors.add(w.add_body(info.vertices, radius=info.radius + bounds.deviation(i, end),
                                   kind="dynamic", position=tuple(pos[i]), angle=w.pose(ids[i])[2],
                                   velocity=tuple(vel[i]), omega=vel3[i][2], gravity=tuple(a0[i]),
                                   mass=1.0, group=info.group, sensor=True,
                                   name=f"{info.name}~{self.windows}"))
        self.windows += 1
        target = t_local if end >= t_local - t0 else t0 + end
        self.window = Window(t0, end, ids, y0, a0, [v[2] for v in vel3], sol,
                             [e for _, e in events], sensors, target)
        try:
            w.step_to(target, events=False)
        except WindowEnd:
            pass
        except Rebuild:
            self._finish(phys, EngineError)
            raise
        self._finish(phys, EngineError)

    def _finish(self, phys: "Physics", EngineError) -> None:
        """The exact state at the window's end (where the world stopped), written back; the
        spring events up to it, in time order."""
        win, self.window = self.window, None
        w = phys.world
        tau = w.time - win.t0
        n = len(win.ids)
        y = win.sol.y[:, -1] if tau >= win.sol.t[-1] else win.sol.sol(tau)
        if w.time >= win.target and win.end < win.sol.t[-1]:
            y = win.sol.sol(win.end)
        for sid in win.sensors:
            w.remove(sid)
        self.dead += len(win.sensors)
        for i, body in enumerate(win.ids):
            x = (float(y[2 * i]), float(y[2 * i + 1]))
            vq = win.y0[2 * n + 2 * i: 2 * n + 2 * i + 2] + win.a0[i] * tau
            ve = w.velocity(body)
            v = (float(y[2 * n + 2 * i] + ve[0] - vq[0]), float(y[2 * n + 2 * i + 1] + ve[1] - vq[1]))
            ob = phys.bodies[body]
            if phys.stale:
                ob.state.x, ob.state.y = x
                ob.state.vx, ob.state.vy = v
                continue
            try:
                w.set_pose(body, x)
            except EngineError:
                pass  # touching within the contact tolerance: the model's pose stands
            w.set_velocity(body, v, ve[2])
        reached = w.time >= win.target
        limit = win.end if reached else tau
        fired = []
        for k, (s, what, length, p) in enumerate(win.events):
            for te in win.sol.t_events[k]:
                if EPS_T < te <= limit and (what != "when" or (reached and te == win.end)):
                    fired.append((te, k, s, what, length, p))
        if self.dead > DEAD_SENSORS and not phys.stale:
            self.dead = 0
            phys.touch()
        for te, _, s, what, length, p in sorted(fired, key=lambda f: (f[0], f[1])):
            if self.on_event is not None:
                self.on_event(s, what, phys.t0 + win.t0 + te, length, p)
