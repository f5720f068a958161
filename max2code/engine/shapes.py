"""Mass, centre of mass and moment of inertia of the engine's shapes.

A shape is a list of vertices (body-frame offsets) and a rounding radius: one vertex is a
circle, two a segment (a capsule when rounded), three or more a convex polygon. Dynamic
bodies turn about their centre of mass, so the World moves a dynamic body's reference point
there and its vertices with it (the numbers come from here).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

Vec = tuple[float, float]


@dataclass(frozen=True)
class MassProperties:
    area: float
    centroid: Vec
    inertia_per_mass: float   # about the centroid: I = mass * inertia_per_mass


def polygon_area(vertices: list[Vec]) -> float:
    """Signed area (positive when anticlockwise)."""
    n = len(vertices)
    return 0.5 * sum(vertices[k][0] * vertices[(k + 1) % n][1]
                     - vertices[(k + 1) % n][0] * vertices[k][1] for k in range(n))


def mass_properties(vertices: list[Vec], radius: float) -> MassProperties:
    """Exact for circles, segments' capsules and sharp polygons; a rounded polygon (radius > 0,
    three or more vertices) counts its rounding as area but takes the core's inertia shape."""
    if len(vertices) == 1:
        return MassProperties(math.pi * radius * radius, vertices[0], radius * radius / 2)
    if len(vertices) == 2:
        (x0, y0), (x1, y1) = vertices
        length = math.hypot(x1 - x0, y1 - y0)
        centre = ((x0 + x1) / 2, (y0 + y1) / 2)
        if radius == 0:  # a thin rod
            return MassProperties(0.0, centre, length * length / 12)
        rect, disc = 2 * radius * length, math.pi * radius * radius
        i_rect = rect * (length * length + 4 * radius * radius) / 12
        # two half-discs: a disc's r^2/2 about its centre, moved to the ends (parallel axis,
        # from each half-disc's own centroid 4r/3pi beyond the end)
        d = 4 * radius / (3 * math.pi)
        arm = length / 2 + d
        i_half = disc / 2 * (radius * radius / 2 - d * d) + disc / 2 * arm * arm
        area = rect + disc
        return MassProperties(area, centre, (i_rect + 2 * i_half) / area)
    area = polygon_area(vertices)
    n = len(vertices)
    cx = cy = 0.0
    for k in range(n):
        (x0, y0), (x1, y1) = vertices[k], vertices[(k + 1) % n]
        cr = x0 * y1 - x1 * y0
        cx += (x0 + x1) * cr
        cy += (y0 + y1) * cr
    cx, cy = cx / (6 * area), cy / (6 * area)
    # second moment about the centroid, per unit area
    j = 0.0
    for k in range(n):
        (x0, y0), (x1, y1) = vertices[k], vertices[(k + 1) % n]
        x0, y0, x1, y1 = x0 - cx, y0 - cy, x1 - cx, y1 - cy
        cr = x0 * y1 - x1 * y0
        j += cr * (x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1)
    j /= 12
    perimeter = sum(math.hypot(vertices[(k + 1) % n][0] - vertices[k][0],
                               vertices[(k + 1) % n][1] - vertices[k][1]) for k in range(n))
    rounded = area + perimeter * radius + math.pi * radius * radius
    return MassProperties(rounded, (cx, cy), j / area)


def compound_mass_properties(parts: list[tuple[list[Vec], float]]) -> MassProperties:
    """Several shapes (vertices, radius) of one density on one rigid body: the areas add, the
    centroid is their area-weighted mean and each part's inertia moves to it by the parallel
    axis theorem (I = sum of a_k (i_k + |c_k - C|^2)). Parts with no area (a thin segment) add
    nothing. A compound with no area at all (thin segments only, its mass given) is rods of one
    line density, weighted by length as a single thin segment is (its L^2/12), not a point
    mass; with no length either (circles whose area underflows), equal point masses."""
    props = [mass_properties(list(v), r) for v, r in parts]
    weights = [p.area for p in props]
    area = sum(weights)
    if not area > 0:
        weights = [math.dist(*v) if len(v) == 2 else 0.0 for v, _ in parts]
        if not sum(weights) > 0:
            weights = [1.0] * len(props)
    total = sum(weights)
    cx = sum(a * p.centroid[0] for a, p in zip(weights, props)) / total
    cy = sum(a * p.centroid[1] for a, p in zip(weights, props)) / total
    second = sum(a * (p.inertia_per_mass + _square(p.centroid[0] - cx) + _square(p.centroid[1] - cy))
                 for a, p in zip(weights, props))
    return MassProperties(area if area > 0 else 0.0, (cx, cy), second / total)


def _square(x: float) -> float:
    """x * x: inf past the float range (a part 1e200 from the centre), where x ** 2 raises
    OverflowError; the core then refuses the infinite inertia by name."""
    return x * x
