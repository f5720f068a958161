"""An independent check of the contact solver's sleep certificate (issue 34): do non-negative
contact forces, inside the friction cones, hold every sleeping body's weight and torque?

Written from the statics, not from the engine: the contacts come from the bodies' poses (a
vertex or circle within `gap` of an edge, a circle within `gap` of a vertex or circle), each
contact's force is a non-negative mix of its friction cone's two edge directions n +- mu t
(exact in the plane), and Lawson & Hanson's active-set NNLS (Solving Least Squares Problems,
1974, ch. 23) finds the mix closest to balance (SciPy's). The residual is the worst body's unbalanced
force over its weight, and torque over weight times size. numpy and SciPy only: the oracle
shares nothing with the C core's projected Gauss-Seidel."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Shape:
    """A body in the world frame: `points` (one for a circle, two for a segment, >= 3 for an
    anticlockwise polygon), its rounding radius, centre of mass, and whether it is held
    (static, or a body outside the checked set that nothing moves)."""
    points: tuple[tuple[float, float], ...]
    radius: float
    centre: tuple[float, float]
    mass: float
    friction: float
    fixed: bool


@dataclass(frozen=True)
class Contact:
    a: int                      # pushed along -normal
    b: int                      # pushed along +normal
    point: tuple[float, float]
    normal: tuple[float, float]  # from a towards b
    mu: float


def world_shapes(world, bodies, fixed_extra=()) -> list[Shape]:
    """The engine's bodies as Shapes at the world's time (poses only: the check is statics)."""
    out = []
    for info in world.bodies:
        x, y, th = world.pose(info.id)
        c, s = math.cos(th), math.sin(th)
        pts = tuple((x + c * px - s * py, y + s * px + c * py) for px, py in info.vertices)
        fixed = info.kind != "dynamic" or info.id not in bodies or info.id in fixed_extra
        out.append(Shape(pts, info.radius, (x, y), info.mass if info.kind == "dynamic" else math.inf,
                         info.friction, fixed))
    return out


def _edges(s: Shape):
    n = len(s.points)
    if n == 2:
        yield s.points[0], s.points[1], True
    elif n >= 3:
        for k in range(n):
            yield s.points[k], s.points[(k + 1) % n], False


def _point_edge(p, r, a, b, two_sided, inside_ref):
    """Distance-gap of a disc (p, r) to edge ab and the normal from the edge towards p, or None
    when p's foot is off the edge."""
    ax, ay = a
    dx, dy = b[0] - ax, b[1] - ay
    L = math.hypot(dx, dy)
    ux, uy = dx / L, dy / L
    along = (p[0] - ax) * ux + (p[1] - ay) * uy
    if along < -1e-12 or along > L + 1e-12:
        return None
    across = (p[0] - ax) * uy - (p[1] - ay) * ux          # > 0: right of a->b (outside, ccw)
    if two_sided:
        sgn = 1.0 if (inside_ref[0] - ax) * uy - (inside_ref[1] - ay) * ux >= 0 else -1.0
    else:
        sgn = 1.0
    return sgn * across - r, (sgn * uy, -sgn * ux), (p[0] - sgn * uy * r, p[1] + sgn * ux * r)


def contacts(shapes: list[Shape], gap: float) -> list[Contact]:
    """Every touching feature pair within `gap` between a free body and anything."""
    found: list[Contact] = []
    n = len(shapes)
    for i in range(n):
        for j in range(n):
            if i == j or (shapes[i].fixed and shapes[j].fixed):
                continue
            A, B = shapes[i], shapes[j]
            mu = math.sqrt(A.friction * B.friction)
            R = A.radius + B.radius
            # points of A against edges of B: normal from B's edge towards A's point
            for p in A.points:
                for a, b, two in _edges(B):
                    hit = _point_edge(p, R, a, b, two, A.centre)
                    if hit is None or hit[0] > gap or hit[0] < -10 * gap - 1e-3 * R:
                        continue
                    g, m, _ = hit
                    q = (p[0] - m[0] * A.radius, p[1] - m[1] * A.radius)
                    if len(A.points) >= 3 and not _cone_ok(A, p, (-m[0], -m[1])):
                        continue
                    found.append(Contact(j, i, q, m, mu))
            # round points against round points (circles, capsule ends): once per pair
            if i < j and R > 0:
                for p in A.points:
                    for q in B.points:
                        d = (q[0] - p[0], q[1] - p[1])
                        L = math.hypot(*d)
                        if L == 0 or L - R > gap:
                            continue
                        m = (d[0] / L, d[1] / L)
                        if _covered(A, B, p, q):
                            continue
                        found.append(Contact(i, j, (p[0] + m[0] * A.radius, p[1] + m[1] * A.radius),
                                             m, mu))
    # a contact listed from both sides (two free bodies, vertex on vertex) is kept once; two
    # at one point along different normals are two (a box's corner in the corner of a floor
    # and a wall: its floor contact was dropped for the wall's end against its side, and the
    # box, lying flat, seemed to hang on the wall)
    unique: dict[tuple, Contact] = {}
    for c in found:
        s = 1.0 if c.a < c.b else -1.0
        key = (min(c.a, c.b), max(c.a, c.b), round(c.point[0], 9), round(c.point[1], 9),
               round(s * c.normal[0], 6), round(s * c.normal[1], 6))
        unique.setdefault(key, c)
    return list(unique.values())


def _cone_ok(A: Shape, p, d) -> bool:
    """A polygon's corner p touches along direction d only when d points out of the body
    (not across it: a box's upper corner is no contact with the floor)."""
    k = A.points.index(p)
    for q in (A.points[k - 1], A.points[(k + 1) % len(A.points)]):
        e = (p[0] - q[0], p[1] - q[1])
        if d[0] * e[0] + d[1] * e[1] < -1e-6 * math.hypot(*e):
            return False
    return True


def _covered(A: Shape, B: Shape, p, q) -> bool:
    """Round point against round point where an edge contact already covers it."""
    for S, x in ((B, p), (A, q)):
        for a, b, _ in _edges(S):
            L = math.dist(a, b)
            along = ((x[0] - a[0]) * (b[0] - a[0]) + (x[1] - a[1]) * (b[1] - a[1])) / L
            if 0 <= along <= L:
                return True
    return False


def nnls(A: np.ndarray, b: np.ndarray) -> np.ndarray:
    """min |A x - b| subject to x >= 0: Lawson & Hanson's active-set algorithm, SciPy's
    compiled one. (A loop of numpy least squares adding one column at a time took 227 s and
    487 s on the 200-disc piles of test_contact_solver, mu 0 and 0.5, against SciPy's 0.11 s
    and 0.15 s, with the same residuals to 1e-13.)"""
    from scipy.optimize import nnls as lawson_hanson

    return lawson_hanson(A, b, maxiter=50 * A.shape[1])[0]


def balance(shapes: list[Shape], found: list[Contact], gravity) -> float:
    """The worst free body's unbalanced force / weight (or torque / (weight size)) under the
    best non-negative cone forces."""
    free = [k for k, s in enumerate(shapes) if not s.fixed]
    if not free:
        return 0.0
    row = {k: 3 * r for r, k in enumerate(free)}
    g = math.hypot(*gravity)
    size = {k: max(math.dist(shapes[k].centre, p) + shapes[k].radius for p in shapes[k].points)
            for k in free}
    cols = []
    for c in found:
        t = (-c.normal[1], c.normal[0])
        for sgn in ((1.0,) if c.mu == 0 else (1.0, -1.0)):
            f = (c.normal[0] + sgn * c.mu * t[0], c.normal[1] + sgn * c.mu * t[1])
            col = np.zeros(3 * len(free))
            for body, s in ((c.b, 1.0), (c.a, -1.0)):
                if body in row:
                    cx, cy = shapes[body].centre
                    rx, ry = c.point[0] - cx, c.point[1] - cy
                    scale = shapes[body].mass * g
                    col[row[body]] += s * f[0] / scale
                    col[row[body] + 1] += s * f[1] / scale
                    col[row[body] + 2] += s * (rx * f[1] - ry * f[0]) / (scale * size[body])
            cols.append(col)
    rhs = np.zeros(3 * len(free))
    for k in free:
        rhs[row[k]] = -gravity[0] / g   # contact forces must cancel the weight m g
        rhs[row[k] + 1] = -gravity[1] / g
    if not cols:
        return 1.0
    A = np.array(cols).T
    x = nnls(A, rhs)
    r = (A @ x - rhs).reshape(-1, 3)
    return float(np.max(np.hypot(r[:, 0], r[:, 1]) + np.abs(r[:, 2])))


def sleeping_residual(world, gap: float = 1e-6) -> float:
    """Balance of every asleep body together (the bodies awake or not dynamic are held)."""
    asleep = {b.id for b in world.bodies if b.kind == "dynamic" and world.asleep(b.id)}
    shapes = world_shapes(world, asleep)
    return balance(shapes, contacts(shapes, gap), world.gravity)
