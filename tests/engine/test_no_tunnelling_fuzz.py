"""No tunnelling in worlds nobody designed (README: "nothing tunnels"): hypothesis builds closed
boxes of circles, capsules and convex polygons at speeds up to 1000 box-widths a second, with
or without gravity, any restitution; at random checkpoints every body is still inside the box
and no two bodies overlap, checked with exact rational geometry on the poses the engine
reports (the engine's own geometry code is not used).

The tolerance is the engine's contact tolerance scaled to the box (a few 1e-9 of its size);
a body that tunnelled through a wall or through another body is metres off, not 1e-9.
"""

from __future__ import annotations

import math
from fractions import Fraction as Q

from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from max2code.engine.world import EngineError

HALF = 5.0                    # the box is [-HALF, HALF]^2
TOL = Q(1, 10**6)             # allowed overlap (the engine's tolerance is 1e-9 relative)

Pt = tuple[Q, Q]


# -- exact geometry --------------------------------------------------------------------------

def world_points(vertices, pose) -> list[Pt]:
    """A body's vertices in the world frame, as exact rationals of the double transform."""
    x, y, a = pose
    c, s = math.cos(a), math.sin(a)
    return [(Q(x) + Q(c) * Q(vx) - Q(s) * Q(vy), Q(y) + Q(s) * Q(vx) + Q(c) * Q(vy))
            for vx, vy in vertices]


def dist2_point_segment(p: Pt, a: Pt, b: Pt) -> Q:
    ex, ey = b[0] - a[0], b[1] - a[1]
    den = ex * ex + ey * ey
    u = Q(0) if den == 0 else min(Q(1), max(Q(0), ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / den))
    dx, dy = p[0] - (a[0] + u * ex), p[1] - (a[1] + u * ey)
    return dx * dx + dy * dy


def edges(pts: list[Pt]) -> list[tuple[Pt, Pt]]:
    if len(pts) == 1:
        return [(pts[0], pts[0])]
    if len(pts) == 2:
        return [(pts[0], pts[1])]
    return [(pts[k], pts[(k + 1) % len(pts)]) for k in range(len(pts))]


def overlaps(p: list[Pt], q: list[Pt]) -> list[tuple[Q, Q]] | None:
    """Separating axes of two convex point sets of which one is a polygon, exactly: None when
    an axis separates them, else each axis's overlap of the projections and the axis's squared
    length (the overlap over its length is the penetration along it; the least is the depth)."""
    if len(p) < 3 and len(q) < 3:
        return None   # points and segments: their distance decides
    out = []
    for pts in (p, q):
        for a, b in edges(pts):
            nx, ny = a[1] - b[1], b[0] - a[0]
            if nx == 0 and ny == 0:
                continue
            pa = [nx * x + ny * y for x, y in p]
            qa = [nx * x + ny * y for x, y in q]
            o = min(max(pa) - min(qa), max(qa) - min(pa))
            if o < 0:
                return None
            out.append((o, nx * nx + ny * ny))
    return out


def too_close(p: list[Pt], rp: float, q: list[Pt], rq: float) -> bool:
    """Do two rounded convex shapes overlap by more than TOL?"""
    R = Q(rp) + Q(rq)
    axes = overlaps(p, q)
    if axes is not None:   # the cores meet: depth + R against TOL
        x = TOL - R
        return x < 0 or all(o * o > x * x * n2 for o, n2 in axes)
    need = R - TOL
    if need <= 0:
        return False
    d2 = min(min(dist2_point_segment(v, a, b) for a, b in edges(q)) for v in p)
    d2 = min(d2, min(min(dist2_point_segment(v, a, b) for a, b in edges(p)) for v in q))
    return d2 < need * need


# -- worlds ----------------------------------------------------------------------------------

def shape(draw) -> tuple[list[tuple[float, float]], float, float]:
    """(vertices, radius, reach): a circle, a capsule or a convex polygon (a regular polygon of
    3-6 sides, stretched), at most 0.6 across."""
    kind = draw(st.sampled_from(["circle", "capsule", "polygon"]))
    size = draw(st.floats(0.05, 0.3))
    if kind == "circle":
        return [(0.0, 0.0)], size, size
    if kind == "capsule":
        r = draw(st.floats(0.02, size / 2))
        return [(-size + r, 0.0), (size - r, 0.0)], r, size
    n = draw(st.integers(3, 6))
    stretch = draw(st.floats(0.5, 1.0))
    verts = [(size * math.cos(2 * math.pi * k / n), stretch * size * math.sin(2 * math.pi * k / n))
             for k in range(n)]
    return verts, 0.0, size


@st.composite
def worlds(draw):
    n = draw(st.integers(2, 7))
    bodies = []
    placed: list[tuple[float, float, float]] = []
    for _ in range(n):
        verts, radius, reach = shape(draw)
        for _attempt in range(40):   # a free spot, reach + 0.01 from the walls and the others
            x = draw(st.floats(-HALF + reach + 0.01, HALF - reach - 0.01))
            y = draw(st.floats(-HALF + reach + 0.01, HALF - reach - 0.01))
            if all(math.hypot(x - a, y - b) > reach + r + 0.01 for a, b, r in placed):
                break
        else:
            continue
        placed.append((x, y, reach))
        speed = draw(st.sampled_from([1.0, 30.0, 1000.0]))
        heading = draw(st.floats(0, 2 * math.pi))
        bodies.append(dict(vertices=verts, radius=radius, position=(x, y),
                           angle=draw(st.floats(0, 2 * math.pi)),
                           velocity=(speed * math.cos(heading), speed * math.sin(heading)),
                           omega=draw(st.sampled_from([0.0, 0.0, 3.0, -40.0])),
                           restitution=draw(st.sampled_from([1.0, 0.9, 0.5]))))
    gravity = draw(st.sampled_from([(0.0, 0.0), (0.0, -9.81)]))
    checkpoints = sorted(draw(st.lists(st.floats(0.001, 1.0), min_size=1, max_size=4)))
    return gravity, bodies, checkpoints


WALLS = [((-HALF, -HALF), (HALF, -HALF)), ((HALF, -HALF), (HALF, HALF)),
         ((HALF, HALF), (-HALF, HALF)), ((-HALF, HALF), (-HALF, -HALF))]


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow],
          phases=(Phase.explicit, Phase.reuse, Phase.generate))   # (a failure prints its world)
@given(world=worlds())
def test_nothing_tunnels_in_random_worlds(engine, world):
    gravity, specs, checkpoints = world
    w = engine.World(gravity=gravity)
    for a, b in WALLS:
        w.add_segment(a, b)
    ids = [w.add_body(**spec) for spec in specs]
    lo, hi = Q(-HALF) - TOL, Q(HALF) + TOL
    for t in checkpoints:
        try:
            w.step_to(t, events=False)
        except EngineError as exc:   # a named condition is allowed; a wrong place is not
            assert "stuck" in str(exc) or "events" in str(exc), exc
            return
        shapes = [(world_points(w.bodies[i].vertices, w.pose(i)), w.bodies[i].radius) for i in ids]
        for k, (pts, r) in enumerate(shapes):
            for x, y in pts:   # inside the box, the radius included
                assert lo + Q(r) <= x <= hi - Q(r) and lo + Q(r) <= y <= hi - Q(r), \
                    f"body {k} left the box at t = {t}: ({float(x)}, {float(y)}) r = {r}"
        for k in range(len(shapes)):
            for j in range(k + 1, len(shapes)):
                assert not too_close(*shapes[k], *shapes[j]), \
                    f"bodies {k} and {j} overlap at t = {t}: {w.pose(ids[k])} {w.pose(ids[j])}"


def test_the_exact_checks_see_an_overlap_and_an_escape():
    """The oracle itself: a square and a circle 1e-3 into it overlap; 1e-3 apart they do not;
    a segment's end point and a capsule are measured from the segment, not its ends only."""
    square = world_points([(-1, -1), (1, -1), (1, 1), (-1, 1)], (0.0, 0.0, 0.0))
    assert too_close(square, 0.0, world_points([(0, 0)], (1.499, 0.0, 0.0)), 0.5)
    assert not too_close(square, 0.0, world_points([(0, 0)], (1.501, 0.0, 0.0)), 0.5)
    seg = world_points([(-1, 0), (1, 0)], (0.0, 0.0, 0.0))
    assert too_close(seg, 0.1, world_points([(0, 0)], (0.0, 0.15, 0.0)), 0.1)
    assert not too_close(seg, 0.1, world_points([(0, 0)], (0.0, 0.25, 0.0)), 0.1)
    # polygons (no radius): a small square inside a big one, and two squares 1e-3 deep
    small = world_points([(-0.1, -0.1), (0.1, -0.1), (0.1, 0.1), (-0.1, 0.1)], (0.0, 0.0, 0.0))
    assert too_close(square, 0.0, small, 0.0)
    assert too_close(square, 0.0, world_points([(-1, -1), (1, -1), (1, 1), (-1, 1)], (1.999, 0.5, 0.0)), 0.0)
    assert not too_close(square, 0.0, world_points([(-1, -1), (1, -1), (1, 1), (-1, 1)], (2.0, 0.5, 0.0)), 0.0)
    assert not too_close(square, 0.0, world_points([(-1, -1), (1, -1), (1, 1), (-1, 1)], (1.9999999, 0.5, 0.0)), 0.0)
