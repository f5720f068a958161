"""The scenes of bench/engine.py, as plain data every engine is built from, and their exact answers.

Every engine (pymunk, Box2D, ours) gets the same bodies: radii, masses, moments of inertia,
restitution, initial state, walls. Friction is zero everywhere, nothing sleeps, nothing is damped.
Units are SI-like (metres, seconds, kilograms): Box2D is tuned for objects of 0.1 to 10 m, and
the scenes stay in that range.

The exact answers are computed here, independently of every engine:
* two discs on straight (or equally accelerated) paths: the smallest positive root of
  |dp + dv t| = r1 + r2, a quadratic;
* a spinning square against a wall: the first time its farthest vertex reaches the wall, on the
  exact trigonometric motion, found by conservative advancement (no contact can be skipped: a
  step never goes past where a vertex could first reach the wall) and bisection in mpmath.
tests/test_bench_engine.py checks these answers against brute force.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field

G = 9.81


@dataclass(frozen=True, kw_only=True)
class Rigid:
    """What every body has: mass, state (position, angle, velocity, spin) and restitution."""

    m: float
    x: float
    y: float
    vx: float = 0.0
    vy: float = 0.0
    angle: float = 0.0
    w: float = 0.0
    e: float = 1.0


@dataclass(frozen=True)
class Disc(Rigid):
    r: float

    @property
    def moment(self) -> float:
        """A solid disc about its centre."""
        return 0.5 * self.m * self.r * self.r


@dataclass(frozen=True)
class Block(Rigid):
    """A convex polygon; vertices relative to its centroid, counter-clockwise."""

    vertices: tuple[tuple[float, float], ...]

    @property
    def area(self) -> float:
        return polygon_area(self.vertices)

    @property
    def moment(self) -> float:
        return polygon_moment(self.vertices, self.m)


@dataclass(frozen=True)
class Wall:
    """A static segment of zero thickness."""

    a: tuple[float, float]
    b: tuple[float, float]
    e: float = 1.0


@dataclass(frozen=True)
class Scene:
    name: str
    bodies: tuple[Disc | Block, ...]
    walls: tuple[Wall, ...] = ()
    gravity: tuple[float, float] = (0.0, 0.0)
    notes: dict = field(default_factory=dict, compare=False)
    # Sustained contact (bench/engine_stacking.py): every contact's Coulomb friction and, when
    # given, its restitution (instead of the bodies' e); `rest`: sleeping allowed and our
    # contact solver on, as an engine is run for stacking.
    friction: float = 0.0
    restitution: float | None = None
    rest: bool = False

    def coefficients(self, body_e: float, friction_mixed: str, restitution_mixed: str) -> tuple[float, float]:
        """What to give each shape (friction, restitution) so that an engine mixing two shapes'
        coefficients by `friction_mixed` / `restitution_mixed` ("product", "sqrt" for sqrt(a b),
        "max") gets the scene's: the same value for every shape, so sqrt and max give it back
        and a product needs its square root."""
        e = body_e if self.restitution is None else self.restitution
        if self.restitution is not None and restitution_mixed == "product":
            e = math.sqrt(e)
        f = math.sqrt(self.friction) if friction_mixed == "product" else self.friction
        return f, e


# --- geometry ----------------------------------------------------------------------------------

def polygon_area(vs) -> float:
    return 0.5 * sum(vs[i - 1][0] * vs[i][1] - vs[i][0] * vs[i - 1][1] for i in range(len(vs)))


def polygon_moment(vs, m: float) -> float:
    """Moment of inertia of a solid polygon of mass m about the origin (its centroid here)."""
    num = den = 0.0
    for i in range(len(vs)):
        (x0, y0), (x1, y1) = vs[i - 1], vs[i]
        cross = x0 * y1 - x1 * y0
        num += cross * (x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1)
        den += cross
    return m * num / (6.0 * den)


def square(half: float) -> tuple[tuple[float, float], ...]:
    return ((-half, -half), (half, -half), (half, half), (-half, half))


def box_walls(x0: float, y0: float, x1: float, y1: float, e: float = 1.0) -> tuple[Wall, ...]:
    return (Wall((x0, y0), (x1, y0), e), Wall((x1, y0), (x1, y1), e),
            Wall((x1, y1), (x0, y1), e), Wall((x0, y1), (x0, y0), e))


def energy(scene: Scene, states) -> float:
    """Kinetic (linear + rotational) plus potential energy, potential zero at y = 0.
    states: (x, y, angle, vx, vy, w) per body, in scene order."""
    gx, gy = scene.gravity
    total = 0.0
    for b, (x, y, _a, vx, vy, w) in zip(scene.bodies, states):
        total += 0.5 * b.m * (vx * vx + vy * vy) + 0.5 * b.moment * w * w - b.m * (gx * x + gy * y)
    return total


# --- 1. tunnelling: a small fast ball against a thin wall -------------------------------------

TUNNEL_RADIUS = 0.01
TUNNEL_SPEEDS = (1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0)


def tunnel_trials(speed: float, trials: int = 200, seed: int = 1) -> list[tuple[Scene, float]]:
    """A ball of radius 0.01 flying at `speed` along +x at a wall x = 0 (a segment from y = -1 to
    1). Its start is spread over a whole frame of travel at the slowest rate measured (1/60 s),
    so the wall falls at every phase of a time step. Returns (scene, end time): the end time is
    when an unhindered ball would be 1 m past the wall."""
    rng = random.Random(seed)
    out = []
    for _ in range(trials):
        gap = 0.5 + rng.random() * max(speed / 60.0, 0.05)
        ball = Disc(TUNNEL_RADIUS, m=0.01, x=-gap - TUNNEL_RADIUS, y=rng.uniform(-0.5, 0.5), vx=speed)
        out.append((Scene("tunnel", (ball,), (Wall((0.0, -1.0), (0.0, 1.0)),)), (gap + 1.0) / speed))
    return out


def tunnelled(final_x: float) -> bool:
    """The ball went through: it is past the wall (a bounced ball is at x < 0)."""
    return final_x > 0.0


# --- 2. contact time of two discs --------------------------------------------------------------

def disc_contact_time(a: Disc, b: Disc) -> float | None:
    """First t > 0 with |p_b - p_a| = r_a + r_b for straight motion (the same gravity on both does
    not change the relative motion); None when they miss."""
    dx, dy = b.x - a.x, b.y - a.y
    ux, uy = b.vx - a.vx, b.vy - a.vy
    rr = a.r + b.r
    qa = ux * ux + uy * uy
    qb = 2 * (dx * ux + dy * uy)
    qc = dx * dx + dy * dy - rr * rr
    disc = qb * qb - 4 * qa * qc
    if qa == 0 or disc < 0 or qb >= 0:
        return None
    # the smaller root, written to avoid cancellation: 2c / (-b + sqrt(disc))
    return 2 * qc / (-qb + math.sqrt(disc))


def two_disc_trials(trials: int = 50, seed: int = 2) -> list[tuple[Scene, float]]:
    """Two discs (radii 0.3 and 0.5, masses 1 and 2) aimed at each other with a random impact
    parameter, first contact between 0.5 s and 1.5 s, at a random phase of every time step."""
    rng = random.Random(seed)
    out = []
    while len(out) < trials:
        t_hit = rng.uniform(0.5, 1.5)
        speed = rng.uniform(1.0, 4.0)
        heading = rng.uniform(0, 2 * math.pi)
        s = rng.uniform(-0.8, 0.8)                   # impact parameter / (r_a + r_b)
        a = Disc(0.3, m=1.0, x=0.0, y=0.0, vx=0.5 * math.cos(heading + 1), vy=0.5 * math.sin(heading + 1))
        ux, uy = speed * math.cos(heading), speed * math.sin(heading)   # velocity of b relative to a
        hx, hy, nx, ny = ux / speed, uy / speed, -uy / speed, ux / speed
        rr = a.r + 0.5
        # relative position at contact: on the circle of radius r_a + r_b, on the side b comes from
        cx = rr * (-hx * math.sqrt(1 - s * s) + nx * s)
        cy = rr * (-hy * math.sqrt(1 - s * s) + ny * s)
        b = Disc(0.5, m=2.0, x=a.x + cx - ux * t_hit, y=a.y + cy - uy * t_hit, vx=a.vx + ux, vy=a.vy + uy)
        t = disc_contact_time(a, b)
        if t is not None and abs(t - t_hit) < 1e-9:
            out.append((Scene("two discs", (a, b)), t))
    return out


# --- 3. rotation: a spinning square against a wall ---------------------------------------------

def square_wall_trials(trials: int = 30, seed: int = 3) -> list[tuple[Scene, float]]:
    """A square (half side 0.25, mass 1) moving at +x and spinning at 2..12 rad/s towards the wall
    x = wall_x; exact first contact from square_wall_contact (grazes are rejected: the farthest
    vertex must cross the wall, not only touch it)."""
    rng = random.Random(seed)
    out = []
    while len(out) < trials:
        half = 0.25
        v = rng.uniform(0.5, 3.0)
        w = rng.choice((-1, 1)) * rng.uniform(2.0, 12.0)
        body = Block(square(half), m=1.0, x=0.0, y=0.0, vx=v, angle=rng.uniform(0, math.pi / 2), w=w)
        wall_x = half * math.sqrt(2) + v * rng.uniform(0.4, 1.2)
        t = square_wall_contact(body, wall_x)
        if t is not None:
            out.append((Scene("spinning square", (body,), (Wall((wall_x, -2.0), (wall_x, 2.0)),),
                              notes={"wall_x": wall_x}), t))
    return out


def square_wall_contact(body: Block, wall_x: float, horizon: float = 5.0, digits: int = 40) -> float | None:
    """First time the polygon's farthest vertex (exact rotation) reaches x = wall_x, or None (no
    contact within the horizon, or a graze that does not cross).

    Conservative advancement with a second-order bound: vertex k's gap g_k(t) = wall_x - x_k(t)
    has |g_k''| <= M = |offset_k| w^2 (no acceleration here), so g_k(t + h) >= g_k + g_k' h -
    M h^2 / 2, and no vertex can reach the wall before the smallest positive root of that bound
    over k. Steps are Newton-like near a crossing and stride over a graze."""
    import mpmath
    with mpmath.workdps(digits):
        verts = [(mpmath.mpf(px), mpmath.mpf(py)) for px, py in body.vertices]
        w, v = mpmath.mpf(body.w), mpmath.mpf(body.vx)

        def gaps(t):
            """(gap, d gap/dt, bound on |d2 gap/dt2|) per vertex."""
            a = mpmath.mpf(body.angle) + w * t
            c, s = mpmath.cos(a), mpmath.sin(a)
            out = []
            for px, py in verts:
                x = mpmath.mpf(body.x) + v * t + c * px - s * py
                dx = v + w * (-s * px - c * py)
                out.append((mpmath.mpf(wall_x) - x, -dx, mpmath.sqrt(px * px + py * py) * w * w))
            return out

        def safe_step(gs):
            best = mpmath.inf
            for g, dg, m in gs:
                if m == 0:
                    h = g / -dg if dg < 0 else mpmath.inf
                else:
                    h = (dg + mpmath.sqrt(dg * dg + 2 * m * g)) / m
                best = min(best, h)
            return best

        def gap(t):
            return min(g for g, _, _ in gaps(t))

        t = mpmath.mpf(0)
        gs = gaps(t)
        if min(g for g, _, _ in gs) <= 0:
            return None
        tiny = mpmath.mpf(10) ** (-digits + 8)
        for _ in range(100000):
            if min(g for g, _, _ in gs) < tiny:
                break
            t += safe_step(gs)
            if t > horizon:
                return None
            gs = gaps(t)
        else:
            raise RuntimeError("conservative advancement did not converge")
        probe = t + mpmath.mpf(10) ** (-digits // 3)
        if gap(probe) >= 0:
            return None              # a graze: the vertex touches and turns away
        lo, hi = t, probe
        for _ in range(4 * digits):
            mid = (lo + hi) / 2
            if gap(mid) > 0:
                lo = mid
            else:
                hi = mid
        return float(lo)


# --- 4. energy: elastic balls in a box with gravity -------------------------------------------

def energy_box(n: int = 20, seed: int = 4) -> Scene:
    """n discs (radius 0.3, mass 1, e = 1) in a 10 m x 10 m box with gravity 9.81, on a jittered
    grid with random velocities of 2..6 m/s; potential energy zero at the floor (y = 0)."""
    rng = random.Random(seed)
    side = 10.0
    cols = math.ceil(math.sqrt(n))
    pitch = side / cols
    bodies = []
    for k in range(n):
        i, j = k % cols, k // cols
        x = pitch * (i + 0.5) + rng.uniform(-0.15, 0.15) * pitch
        y = pitch * (j + 0.5) + rng.uniform(-0.15, 0.15) * pitch
        speed, heading = rng.uniform(2, 6), rng.uniform(0, 2 * math.pi)
        bodies.append(Disc(0.3, m=1.0, x=x, y=y, vx=speed * math.cos(heading), vy=speed * math.sin(heading)))
    return Scene("energy box", tuple(bodies), box_walls(0, 0, side, side), (0.0, -G))


# --- 5. cost: a gas of discs, sparse and dense -------------------------------------------------

GAS_RADIUS = 1.0
# Area fraction of the discs and their speed, chosen for the contact rates of DESIGN.md section 8
# (new touching pairs per simulated second, sparse 2 / 10 / 74 and dense 29 / 216 / 1840 for
# N = 10 / 100 / 1000). pymunk at dt = 1/240, 3 seeds of 200 / 50 / 15 s, counts 1.9 / 10.7 / 80
# and 30 / 210 / 1833 (the same within 4 % over the first 20 / 10 / 3 s: the uniform start is
# already stationary). Hard discs: the rate is proportional to the speed, nothing else changes;
# the speeds are well above Box2D's 1 m/s restitution threshold.
GAS = {"sparse": {"fraction": 0.02, "speed": 4.0},
       "dense": {"fraction": 0.25, "speed": 5.5}}


def scatter(n: int, r: float, side: float, rng: random.Random) -> list[tuple[float, float]]:
    """n non-overlapping disc centres, uniform in the square [0, side]^2 (random sequential
    placement; the discs are clear of the walls and of each other by 1 % of r)."""
    cell = 2.02 * r
    cells: dict[tuple[int, int], list[tuple[float, float]]] = {}
    out = []
    tries = 0
    while len(out) < n:
        tries += 1
        if tries > 1000 * n:
            raise ValueError("too dense to place the discs")
        x, y = rng.uniform(1.01 * r, side - 1.01 * r), rng.uniform(1.01 * r, side - 1.01 * r)
        ci, cj = int(x // cell), int(y // cell)
        if any((x - px) ** 2 + (y - py) ** 2 < cell * cell
               for di in (-1, 0, 1) for dj in (-1, 0, 1) for px, py in cells.get((ci + di, cj + dj), ())):
            continue
        cells.setdefault((ci, cj), []).append((x, y))
        out.append((x, y))
    return out


def gas(n: int, kind: str, speed: float | None = None, seed: int = 5) -> Scene:
    """n discs (radius 1, mass 1, e = 1) scattered uniformly in a square box sized for the kind's
    area fraction, random directions at one speed, no gravity."""
    spec = GAS[kind]
    speed = spec["speed"] if speed is None else speed
    rng = random.Random(seed * 7919 + n)
    side = math.sqrt(n * math.pi * GAS_RADIUS ** 2 / spec["fraction"])
    bodies = []
    for x, y in scatter(n, GAS_RADIUS, side, rng):
        heading = rng.uniform(0, 2 * math.pi)
        bodies.append(Disc(GAS_RADIUS, m=1.0, x=x, y=y, vx=speed * math.cos(heading), vy=speed * math.sin(heading)))
    return Scene(f"{kind} gas N={n}", tuple(bodies), box_walls(0, 0, side, side),
                 notes={"side": side, "speed": speed})


def idle(n: int = 100, seed: int = 6) -> Scene:
    """n discs (radius 1) drifting slowly far apart (8 m pitch, 0.01 m/s, no gravity) in a box
    they do not reach within 60 s: nothing collides, only frames happen."""
    rng = random.Random(seed)
    cols = math.ceil(math.sqrt(n))
    bodies = []
    for k in range(n):
        i, j = k % cols, k // cols
        heading = rng.uniform(0, 2 * math.pi)
        bodies.append(Disc(GAS_RADIUS, m=1.0, x=8.0 * i + 4, y=8.0 * j + 4, vx=0.01 * math.cos(heading),
                           vy=0.01 * math.sin(heading)))
    return Scene(f"idle N={n}", tuple(bodies), box_walls(0, 0, 8.0 * cols, 8.0 * cols))
