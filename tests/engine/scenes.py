"""Worlds the tests share (made here, not read from the engine)."""

from __future__ import annotations

import math
import random


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
