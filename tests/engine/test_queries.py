"""Queries at any time >= now (issue 35): point, axis-aligned box and ray cast, against closed
forms and, for the ray's exact first hit, against an independent gap oracle
(max2code.engine.geometry, the scene checker's exact geometry)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from max2code.engine.geometry import gap, transform
from .scenes import engine_floats


def _world(engine):
    w = engine.World()
    floor = w.add_segment((-5.0, 0.0), (5.0, 0.0))
    ball = w.add_circle((0.0, 2.0), 0.5, velocity=(1.0, 0.0), category=2)
    box = w.add_polygon([(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)], kind="static",
                        position=(4.0, 3.0))
    cap = w.add_segment((0.0, 0.0), (1.0, 0.0), radius=0.25, kind="static", position=(-3.0, 3.0))
    return w, floor, ball, box, cap


def test_point_queries_follow_the_motion(engine) -> None:
    w, floor, ball, box, cap = _world(engine)
    assert w.query_point((0.2, 2.2)) == [ball]
    assert w.query_point((1.2, 2.2)) == [] and w.query_point((1.2, 2.2), t=1.0) == [ball]
    assert w.query_point((4.5, 3.5)) == [box]
    assert w.query_point((-3.1, 3.2)) == [cap] and w.query_point((-3.2, 3.2)) == []
    assert w.query_point((0.2, 2.2), mask=1) == []          # the ball is category 2
    with pytest.raises(engine.EngineError, match="not before now"):
        w.step_to(1.0) or w.query_point((0.0, 0.0), t=0.5)


def test_box_queries(engine) -> None:
    w, floor, ball, box, cap = _world(engine)
    assert w.query_box((-10.0, -1.0), (10.0, 0.1)) == [floor]
    assert w.query_box((-1.0, 1.4), (1.0, 1.6)) == [ball]
    assert w.query_box((-1.0, 1.4), (1.0, 1.49)) == []
    assert w.query_box((2.9, 3.0), (3.1, 3.2)) == [box]
    assert sorted(w.query_box((-10.0, -10.0), (10.0, 10.0))) == [floor, ball, box, cap]


def test_ray_casts(engine) -> None:
    w, floor, ball, box, cap = _world(engine)
    hit = w.cast_ray((0.0, 10.0), (0.0, -10.0))
    assert (hit.body, hit.point, hit.normal, hit.fraction) == (ball, (0.0, 2.5), (0.0, 1.0), 0.375)
    hit = w.cast_ray((-2.0, 5.0), (-2.0, -5.0))            # the end of the capsule's flat side
    assert hit.body == cap and hit.point[1] == pytest.approx(3.25, rel=1e-15)
    hit = w.cast_ray((-1.9, 5.0), (-1.9, -5.0))
    assert hit.body == cap and hit.point[1] == pytest.approx(3.0 + math.sqrt(0.25 ** 2 - 0.1 ** 2), rel=1e-15)
    assert w.cast_ray((-10.0, 2.0), (10.0, 2.0), t=5.0).body == box   # the ball is at x = 5 then
    assert w.cast_ray((0.0, 2.0), (0.0, 10.0)) is None      # starts inside the ball
    assert w.cast_ray((-10.0, 8.0), (10.0, 8.0)) is None


@settings(max_examples=60, deadline=None)
@given(n=st.integers(1, 6), size=engine_floats(0.2, 2.0), radius=engine_floats(0.0, 0.5),
       angle=engine_floats(0.0, 6.3), sx=engine_floats(-6.0, 6.0), sy=engine_floats(-6.0, 6.0),
       heading=engine_floats(0.0, 6.3))
def test_ray_hit_is_the_first_touch(engine, n, size, radius, angle, sx, sy, heading) -> None:
    """The hit point touches the shape (gap 0 within rounding) and the ray before it is apart
    (gap > 0 at 200 points): the first root, exactly."""
    if n == 1 and radius < 0.05:
        radius = 0.05
    verts = [(0.0, 0.0)] if n == 1 else [(size * math.cos(2 * math.pi * k / n),
                                            size * math.sin(2 * math.pi * k / n)) for k in range(n)]
    if n == 2:
        verts = [(-size, 0.0), (size, 0.0)]
    w = engine.World()
    body = w.add_body(verts, radius=radius, kind="static", angle=angle)
    shape = transform(w.bodies[body].vertices, w.pose(body))
    start = (sx, sy)
    end = (sx + 20 * math.cos(heading), sy + 20 * math.sin(heading))
    if gap([start], 0.0, shape, radius) <= 1e-12:
        return                                               # starts inside or on it
    hit = w.cast_ray(start, end)
    along = lambda f: (start[0] + f * (end[0] - start[0]), start[1] + f * (end[1] - start[1]))
    if hit is None:
        assert all(gap([along(k / 400)], 0.0, shape, radius) > -1e-9 for k in range(401))
        return
    assert abs(gap([hit.point], 0.0, shape, radius)) <= 1e-9
    assert all(gap([along(hit.fraction * k / 200)], 0.0, shape, radius) > -1e-9 for k in range(200))
