"""Exact-geometry distances between the engine's shapes (independent of the C core).

A shape's core is its vertices in world coordinates: one point, a segment (two) or a convex
polygon (three or more, anticlockwise); its surface lies `radius` beyond the core. The scene
checker uses these to refuse bodies that start overlapping, and the tests to check that no
event or frame ever shows an overlap beyond the tolerance.
"""

from __future__ import annotations

import math
from typing import Sequence

Vec = tuple[float, float]


def transform(vertices: Sequence[Vec], pose: tuple[float, float, float]) -> list[Vec]:
    """Body-frame vertices -> world coordinates at pose (x, y, angle)."""
    x, y, a = pose
    c, s = math.cos(a), math.sin(a)
    return [(x + c * vx - s * vy, y + s * vx + c * vy) for vx, vy in vertices]


def _edges(p: Sequence[Vec]) -> list[tuple[Vec, Vec]]:
    if len(p) == 1:
        return []
    if len(p) == 2:
        return [(p[0], p[1])]
    return [(p[k], p[(k + 1) % len(p)]) for k in range(len(p))]


def point_segment(p: Vec, a: Vec, b: Vec) -> float:
    dx, dy = b[0] - a[0], b[1] - a[1]
    ll = dx * dx + dy * dy
    u = 0.0 if ll == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / ll))
    return math.hypot(p[0] - a[0] - u * dx, p[1] - a[1] - u * dy)


def _orient(a: Vec, b: Vec, c: Vec) -> float:
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def _segments_cross(a: Vec, b: Vec, c: Vec, d: Vec) -> bool:
    o1, o2, o3, o4 = _orient(a, b, c), _orient(a, b, d), _orient(c, d, a), _orient(c, d, b)
    return (o1 > 0) != (o2 > 0) and (o3 > 0) != (o4 > 0) and o1 * o2 < 0 and o3 * o4 < 0


def _inside(p: Vec, poly: Sequence[Vec]) -> bool:
    """Strictly inside a convex anticlockwise polygon."""
    return len(poly) >= 3 and all(_orient(a, b, p) > 0 for a, b in _edges(poly))


def _penetration(P: Sequence[Vec], Q: Sequence[Vec]) -> float:
    """How far the cores overlap along the best separating direction (>= 0)."""
    depth = math.inf
    for poly in (P, Q):
        if len(poly) < 2:
            continue
        for a, b in _edges(poly):
            nx, ny = b[1] - a[1], a[0] - b[0]
            n = math.hypot(nx, ny)
            if n == 0:
                continue
            nx, ny = nx / n, ny / n
            pa = [x * nx + y * ny for x, y in P]
            qa = [x * nx + y * ny for x, y in Q]
            # the shorter push that separates them along this axis (not the intervals'
            # common length, which is 0 for a thin segment however deep a shape crosses it)
            depth = min(depth, min(max(pa) - min(qa), max(qa) - min(pa)))
    return max(depth, 0.0) if math.isfinite(depth) else 0.0


def core_distance(P: Sequence[Vec], Q: Sequence[Vec]) -> float:
    """Distance between two convex cores; minus the penetration depth when they intersect."""
    crossing = any(_segments_cross(a, b, c, d) for a, b in _edges(P) for c, d in _edges(Q))
    if crossing or any(_inside(p, Q) for p in P) or any(_inside(q, P) for q in Q):
        return -_penetration(P, Q)
    best = math.inf
    for X, Y in ((P, Q), (Q, P)):
        for p in X:
            if len(Y) == 1:
                best = min(best, math.hypot(p[0] - Y[0][0], p[1] - Y[0][1]))
            for a, b in _edges(Y):
                best = min(best, point_segment(p, a, b))
    return best


def gap(P: Sequence[Vec], rp: float, Q: Sequence[Vec], rq: float) -> float:
    """Signed distance between two rounded shapes (negative: they overlap by that much)."""
    return core_distance(P, Q) - rp - rq
