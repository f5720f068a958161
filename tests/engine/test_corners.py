"""Exact corners and channels (issue 33, item 3): simultaneous contacts, contacts at zero speed.

An e = 1 ball going exactly into a 90-degree corner touches both walls at one instant: it
must leave with both normal components reflected and its energy kept (it left with one of
them zeroed and half its energy: the rest rule's inelastic projection took the second wall
as a support). An e = 1 ball sliding through a channel exactly its diameter wide has zero
normal speed on both walls and must get no impulse at all (at the exit the double root of the
vertex contact, split by rounding, was taken as an impact, and the projection stopped the
ball dead: energy 0.0245 -> 4e-60).

The scenes use dyadic coordinates, speeds and times, so every touch is exact; the closed
forms are the reflections of the velocity (corner) and the entry velocity (channel). Each
scene is also turned by 0, 90, 180 and 270 degrees (exactly: coordinates swapped and negated)
and built of thin segments or of static polygon slabs, which changes the features and the
order in which the simultaneous contacts come.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings, strategies as st

Vec = tuple[float, float]

TURNS = (lambda p: (p[0], p[1]), lambda p: (-p[1], p[0]),
         lambda p: (-p[0], -p[1]), lambda p: (p[1], -p[0]))


def slab(world, turn, x0: float, y0: float, x1: float, y1: float) -> int:
    """A static rectangle [x0, x1] x [y0, y1], turned."""
    return world.add_polygon([turn(p) for p in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))],
                             kind="static")


def box_walls(world, turn, w: float, h: float, polygons: bool) -> None:
    """The inside of [0, w] x [0, h]: four segments, or four slabs one unit thick."""
    if polygons:
        slab(world, turn, -1, -1, w + 1, 0)
        slab(world, turn, -1, h, w + 1, h + 1)
        slab(world, turn, -1, 0, 0, h)
        slab(world, turn, w, 0, w + 1, h)
        return
    corners = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)]
    for k in range(4):
        world.add_segment(turn(corners[k]), turn(corners[(k + 1) % 4]))


def corner_shot(World, turn, polygons: bool, w: float, h: float, r: float, corner: tuple[int, int],
                v: Vec, t_hit: float):
    """A ball of radius r that touches both walls of a corner of the box at t_hit exactly.
    Returns (world, ball, velocity in the box's frame)."""
    sx, sy = corner                      # 0: the corner at the low side, 1: at the high side
    cx = r if sx == 0 else w - r         # the ball's centre at the hit
    cy = r if sy == 0 else h - r
    vx = -abs(v[0]) if sx == 0 else abs(v[0])
    vy = -abs(v[1]) if sy == 0 else abs(v[1])
    world = World(gravity=(0.0, 0.0))
    box_walls(world, turn, w, h, polygons)
    ball = world.add_circle(turn((cx - vx * t_hit, cy - vy * t_hit)), r, velocity=turn((vx, vy)))
    return world, ball, (vx, vy)


def check_corner(World, turn, polygons, w, h, r, corner, v, t_hit) -> None:
    world, ball, (vx, vy) = corner_shot(World, turn, polygons, w, h, r, corner, v, t_hit)
    e0 = world.energy()
    # after the hit, until halfway to the opposite walls: nothing else happens
    after = 0.5 * min((w - 2 * r) / abs(vx), (h - 2 * r) / abs(vy))
    events = world.step_to(t_hit + after)
    hits = [e for e in events if e.kind == "collision"]
    # both at one instant (the root finder's time is within an ulp or two of the exact one)
    assert len(hits) == 2 and hits[0].time == hits[1].time, [(e.time, e.b) for e in hits]
    assert hits[0].time == pytest.approx(t_hit, rel=1e-14)
    got = world.velocity(ball)
    want = turn((-vx, -vy))
    assert got[0] == pytest.approx(want[0], rel=1e-12) and got[1] == pytest.approx(want[1], rel=1e-12)
    assert got[2] == 0.0
    assert world.energy() == pytest.approx(e0, rel=1e-12)
    # and the pose is the reflected motion's
    x, y, _ = world.pose(ball)
    cx = r if corner[0] == 0 else w - r
    cy = r if corner[1] == 0 else h - r
    px, py = turn((cx - vx * after, cy - vy * after))
    assert x == pytest.approx(px, abs=1e-9) and y == pytest.approx(py, abs=1e-9)


def channel_run(World, turn, polygons: bool, r: float, length: float, start: float, speed: float):
    """A channel from x = 0 to `length`, exactly 2 r wide (walls y = 0 and y = 2 r); a ball of
    radius r on its axis at x = start, moving along it at `speed` (either sign)."""
    world = World(gravity=(0.0, 0.0))
    if polygons:
        slab(world, turn, 0, -1, length, 0)
        slab(world, turn, 0, 2 * r, length, 2 * r + 1)
    else:
        world.add_segment(turn((0.0, 0.0)), turn((length, 0.0)))
        world.add_segment(turn((0.0, 2 * r)), turn((length, 2 * r)))
    ball = world.add_circle(turn((start, r)), r, velocity=turn((speed, 0.0)))
    return world, ball


def check_channel(World, turn, polygons, r, length, start, speed) -> None:
    world, ball = channel_run(World, turn, polygons, r, length, start, speed)
    e0 = world.energy()
    end = length + 2 * r if speed > 0 else -2 * r      # out of the channel beyond it
    t_out = (end - start) / speed
    events = world.step_to(t_out)
    assert [e for e in events if e.kind == "collision"] == []      # no impulse at all
    vx, vy, w = world.velocity(ball)
    want = turn((speed, 0.0))
    assert (vx, vy, w) == (want[0], want[1], 0.0)
    assert world.energy() == pytest.approx(e0, rel=1e-12)
    assert world.pose(ball)[:2] == pytest.approx(turn((end, r)), abs=1e-9)


# ----------------------------------------------------------------------------- the reported scenes

@pytest.mark.parametrize("polygons", [False, True])
def test_ball_exactly_into_a_corner_leaves_reflected_in_both_axes(engine, polygons) -> None:
    """The reported scene: walls x = 0 and y = 0, a ball of radius 0.5 from (2.5, 2.5) at
    (-1, -1) touches both at t = 2. It left with (1, 0) or (0, 1), half its energy."""
    check_corner(engine.World, TURNS[0], polygons, 10.0, 10.0, 0.5, (0, 0), (1.0, 1.0), 2.0)


@pytest.mark.parametrize("polygons", [False, True])
def test_ball_through_a_channel_of_its_diameter_keeps_its_speed(engine, polygons) -> None:
    """The reported scene: a channel 0.5 wide (turned by 180 degrees), a ball of radius 0.25
    at 0.5 m/s, energy 0.0245. It stopped dead at the exit (energy 4e-60 and less)."""
    check_channel(engine.World, TURNS[2], polygons, 0.25, 4.0, 0.0 if polygons else -1.0, 0.5)


def test_corner_shifted_by_a_little_is_two_contacts_too(engine) -> None:
    """Shifted by 1e-7 the walls are hit one after the other: the same exit velocity."""
    w = engine.World(gravity=(0.0, 0.0))
    w.add_segment((0, 0), (0, 10))
    w.add_segment((0, 0), (10, 0))
    ball = w.add_circle((2.5 + 1e-7, 2.5), 0.5, velocity=(-1, -1))
    e0 = w.energy()
    w.step_to(3.0)
    assert w.velocity(ball)[:2] == pytest.approx((1.0, 1.0), rel=1e-12)
    assert w.energy() == pytest.approx(e0, rel=1e-12)


def test_a_ball_pressed_into_a_corner_still_rests_there(engine) -> None:
    """The rest rule's projection still holds what it should: a ball in a corner with gravity
    into both walls and a slow push into them falls asleep there and does not sink in."""
    w = engine.World(gravity=(-4.0, -4.0))
    w.add_segment((0, 0), (0, 10))
    w.add_segment((0, 0), (10, 0))
    ball = w.add_circle((0.5, 0.5), 0.5, velocity=(-1e-4, -2e-4), restitution=0.5)
    w.step_to(2.0)
    x, y, _ = w.pose(ball)
    assert w.asleep(ball)
    assert x == pytest.approx(0.5, abs=1e-9) and y == pytest.approx(0.5, abs=1e-9)


# ------------------------------------------------------------------------------- the properties

dyadic = st.integers(1, 64).map(lambda k: k / 16)       # 1/16 .. 4, exact


@settings(max_examples=80, deadline=None)
@given(turn=st.integers(0, 3), polygons=st.booleans(),
       w=st.integers(4, 40).map(lambda k: k / 4), h=st.integers(4, 40).map(lambda k: k / 4),
       r=st.integers(1, 8).map(lambda k: k / 32), corner=st.tuples(st.integers(0, 1), st.integers(0, 1)),
       vx=dyadic, vy=dyadic, frac=st.integers(1, 7).map(lambda k: k / 8))
def test_any_ball_exactly_into_any_corner(engine, turn, polygons, w, h, r, corner, vx, vy, frac) -> None:
    """Random boxes, radii, corners, speeds and directions; the ball starts inside the box at
    a dyadic point on the line into the corner (a fraction of the way back to the far walls)."""
    # time back to where the ball's line crosses the far side of the box: the start lies inside
    reach = min((w - 2 * r) / vx, (h - 2 * r) / vy)       # >= 1/8
    t_hit = max(1, int(frac * reach * 64)) / 64
    check_corner(engine.World, TURNS[turn], polygons, w, h, r, corner, (vx, vy), t_hit)


@settings(max_examples=80, deadline=None)
@given(turn=st.integers(0, 3), polygons=st.booleans(), r=st.integers(1, 32).map(lambda k: k / 32),
       length=st.integers(1, 64).map(lambda k: k / 8), where=st.sampled_from(["before", "inside", "mouth"]),
       speed=dyadic, backwards=st.booleans())
def test_any_ball_through_any_channel_of_its_diameter(engine, turn, polygons, r, length, where,
                                                      speed, backwards) -> None:
    """Random radii, lengths, speeds and directions; the ball starts before the channel, in
    it, or exactly at its mouth (touching the walls' ends)."""
    start = {"before": -1.0 - r, "inside": length / 2, "mouth": 0.0}[where]
    if backwards:
        start = length - start
        speed = -speed
    check_channel(engine.World, TURNS[turn], polygons, r, length, start, speed)
