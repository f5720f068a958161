"""The distance between two engine bodies (convex polygons, segments or circles, each with a
rounding radius) at given poses: the springs' predictor sizes its windows by it."""

from __future__ import annotations

import math
from typing import Sequence

Vec = tuple[float, float]


def placed(vertices: Sequence[Vec], pose: tuple[float, float, float]) -> list[Vec]:
    x, y, a = pose
    c, s = math.cos(a), math.sin(a)
    return [(x + c * u - s * v, y + s * u + c * v) for u, v in vertices]


def _point_segment(p: Vec, a: Vec, b: Vec) -> float:
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = dx * dx + dy * dy
    t = 0.0 if n == 0.0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / n))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def _edges(pts: list[Vec]) -> list[tuple[Vec, Vec]]:
    if len(pts) == 1:
        return [(pts[0], pts[0])]
    if len(pts) == 2:
        return [(pts[0], pts[1])]
    return [(pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts))]


def _inside(p: Vec, pts: list[Vec]) -> bool:
    """p inside the convex polygon pts (anticlockwise, as the engine keeps them)."""
    if len(pts) < 3:
        return False
    return all((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= 0
               for a, b in _edges(pts))


def _cross(a: Vec, b: Vec, c: Vec) -> float:
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def _segments_cross(p: Vec, q: Vec, r: Vec, s: Vec) -> bool:
    return (_cross(p, q, r) * _cross(p, q, s) < 0) and (_cross(r, s, p) * _cross(r, s, q) < 0)


def gap(a: list[Vec], ra: float, b: list[Vec], rb: float) -> float:
    """The distance between two placed convex shapes with rounding radii (0 when they
    overlap). Between convex sets the closest pair always has a vertex at one end, so the
    vertex-edge distances both ways give it."""
    if any(_inside(p, b) for p in a) or any(_inside(p, a) for p in b):
        return 0.0
    if any(_segments_cross(*e, *f) for e in _edges(a) for f in _edges(b)):
        return 0.0
    d = min(min(_point_segment(p, e0, e1) for e0, e1 in _edges(b)) for p in a)
    d = min(d, min(min(_point_segment(p, e0, e1) for e0, e1 in _edges(a)) for p in b))
    return max(0.0, d - ra - rb)
