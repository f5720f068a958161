"""Worlds the tests share (made here, not read from the engine)."""

from __future__ import annotations

import math
import random

from max2code.engine.geometry import gap, transform


def box(world, width: float, height: float, restitution: float = 1.0) -> list[int]:
    corners = [(0.0, 0.0), (width, 0.0), (width, height), (0.0, height)]
    return [world.add_segment(corners[k], corners[(k + 1) % 4], restitution=restitution)
            for k in range(4)]


def scatter(rng: random.Random, n: int, radius: float, width: float, height: float,
            gap: float = 0.01) -> list[tuple[float, float]]:
    """n centres inside the box, no two closer than 2 radius + gap (rejection sampling)."""
    out: list[tuple[float, float]] = []
    while len(out) < n:
        x = rng.uniform(radius + gap, width - radius - gap)
        y = rng.uniform(radius + gap, height - radius - gap)
        if all(math.hypot(x - a, y - b) > 2 * radius + gap for a, b in out):
            out.append((x, y))
    return out


def gas(World, n: int, radius: float, size: float, speed: float, seed: int, *, gravity=(0.0, 0.0),
        walls: bool = True, restitution: float = 1.0, **kw):
    """n balls with random velocities in a size x size box (or free, walls=False)."""
    rng = random.Random(seed)
    w = World(gravity=gravity, **kw)
    if walls:
        box(w, size, size)
    for x, y in scatter(rng, n, radius, size, size):
        w.add_circle((x, y), radius, velocity=(rng.uniform(-speed, speed), rng.uniform(-speed, speed)),
                     restitution=restitution, mass=rng.uniform(0.5, 2.0))
    return w


def spinning_gas(World, seed: int, walls: bool, friction: float = 0.0):
    """14 circles, capsules and polygons spinning in an 8 x 8 box (or free, walls=False)."""
    rng = random.Random(seed)
    w = World()
    if walls:
        for a, b in [((0, 0), (8, 0)), ((8, 0), (8, 8)), ((8, 8), (0, 8)), ((0, 8), (0, 0))]:
            w.add_segment(a, b, friction=friction)
    pts: list[tuple[float, float]] = []
    while len(pts) < 14:
        x, y = rng.uniform(0.8, 7.2), rng.uniform(0.8, 7.2)
        if all(math.hypot(x - a, y - b) > 1.5 for a, b in pts):
            pts.append((x, y))
    for k, (x, y) in enumerate(pts):
        v, om = (rng.uniform(-2, 2), rng.uniform(-2, 2)), rng.uniform(-4, 4)
        if k % 4 == 0:
            w.add_circle((x, y), 0.4, velocity=v, omega=om, friction=friction)
        elif k % 4 == 1:
            w.add_segment((-0.5, 0.0), (0.5, 0.0), radius=0.1, kind="dynamic", position=(x, y),
                          velocity=v, omega=om, friction=friction)
        else:
            n = 3 + k % 3
            vs = [(0.55 * math.cos(2 * math.pi * i / n), 0.55 * math.sin(2 * math.pi * i / n)) for i in range(n)]
            w.add_polygon(vs, position=(x, y), velocity=v, omega=om, friction=friction)
    return w


def assert_apart(world, t: float | None = None, tol: float | None = None) -> float:
    """No two bodies (one of them dynamic) overlap by more than tol at time t (default: now),
    by exact geometry; returns the smallest gap. The default tol is 1e-9, plus the contact
    solver's slop where it is on (pairs it holds may keep that overlap: engine-contact.md)."""
    if tol is None:
        tol = 1e-9 + world.contact_slop
    shapes = [(b, transform(b.vertices, world.pose(b.id, t))) for b in world.bodies]
    worst = math.inf
    for i, (a, pa) in enumerate(shapes):
        for b, pb in shapes[i + 1:]:
            if "dynamic" in (a.kind, b.kind):
                g = gap(pa, a.radius, pb, b.radius)
                assert g >= -tol, f"{a.name} and {b.name} overlap by {-g} at t = {world.time if t is None else t}"
                worst = min(worst, g)
    return worst


def engine_floats(lo: float, hi: float):
    """hypothesis' floats in [lo, hi], a magnitude below 1e-30 drawn as 0: the API refuses such
    a number as a scene file does (limits.magnitude_problem), and hypothesis likes to draw them
    (subnormals near 0) where a test means an ordinary coordinate, angle or time."""
    from hypothesis import strategies as st

    from max2code.engine import limits
    return st.floats(lo, hi).map(lambda x: x if abs(x) >= limits.SMALLEST else 0.0)


def core_body(w, vertices, radius: float = 0.0, kind: int = 2, position=(0.0, 0.0),
              velocity=(0.0, 0.0), omega: float = 0.0, gravity=(0.0, 0.0), mass: float = 1.0,
              inertia: float = 1.0) -> int:
    """Add a body to World w's core through the core's own C API (m2c_world_add_body),
    bypassing the Python API's checks (limits.py refuses a mass of 1e308, an omega of 1e308):
    how the tests reach the core's own guards (stuck, overflow) with numbers only a C caller
    can still give. The body is not in w.bodies; pose(id) and velocity(id) read it."""
    d = w._ffi.new("m2c_body_def *", w._lib.m2c_default_body_def())
    flat = w._ffi.new("double[]", [c for p in vertices for c in p])
    d.kind, (d.x, d.y), (d.vx, d.vy), d.omega = kind, position, velocity, omega
    (d.ax, d.ay), d.mass, d.inertia = gravity, mass, inertia
    d.nvertices, d.vertices, d.radius = len(vertices), flat, radius
    i = w._lib.m2c_world_add_body(w._w, d)
    assert i >= 0, w.error()
    return i
