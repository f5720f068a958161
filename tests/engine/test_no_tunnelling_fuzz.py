"""No tunnelling in worlds nobody designed (README: "nothing tunnels"): hypothesis builds closed
boxes of circles, capsules and convex polygons at speeds up to 1000 box-widths a second, with
or without gravity, any restitution; at every impact (its two bodies) and at random checkpoints
(every pair) every body is still inside the box and no two bodies overlap, checked with exact
rational geometry on the poses the engine reports (the engine's own geometry code is not used),
and the energy stays within its documented bound. bench/tunnelling_fuzz.py is the long run.

The tolerance is the engine's contact tolerance scaled to the box (a few 1e-9 of its size);
a body that tunnelled through a wall or through another body is metres off, not 1e-9.
"""

from __future__ import annotations

import math
from fractions import Fraction as Q

import pytest
from hypothesis import HealthCheck, Phase, example, given, settings
from hypothesis import strategies as st

from max2code.engine.world import EngineError
from .scenes import engine_floats

HALF = 5.0                    # the box is [-HALF, HALF]^2
TOL = Q(1, 10**6)             # allowed overlap (the engine's tolerance is 1e-9 relative)
STEP = 1 / 240                # the contact solver's default step h

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


def cross(o: Pt, a: Pt, b: Pt) -> Q:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def segments_meet(p: list[Pt], q: list[Pt]) -> bool:
    """Do two segments (or points) cross or touch, exactly? Two capsules' cores can cross
    with every end point farther than the radii from the other segment (a capsule stuck
    through a wall): their distance is 0, which the end points' distances do not show."""
    a, b = p[0], p[-1]
    c, d = q[0], q[-1]
    d1, d2, d3, d4 = cross(a, b, c), cross(a, b, d), cross(c, d, a), cross(c, d, b)
    return d1 * d2 < 0 and d3 * d4 < 0


def too_close(p: list[Pt], rp: float, q: list[Pt], rq: float, tol: Q = TOL) -> bool:
    """Do two rounded convex shapes overlap by more than tol?"""
    R = Q(rp) + Q(rq)
    axes = overlaps(p, q)
    if axes is not None:   # the cores meet: depth + R against tol
        x = tol - R
        return x < 0 or all(o * o > x * x * n2 for o, n2 in axes)
    need = R - tol
    if need <= 0:
        return False
    if len(p) < 3 and len(q) < 3 and segments_meet(p, q):
        return True        # the cores cross: the overlap is at least R
    d2 = min(min(dist2_point_segment(v, a, b) for a, b in edges(q)) for v in p)
    d2 = min(d2, min(min(dist2_point_segment(v, a, b) for a, b in edges(p)) for v in q))
    return d2 < need * need


# -- worlds ----------------------------------------------------------------------------------

def shape(draw) -> tuple[list[tuple[float, float]], float, float]:
    """(vertices, radius, reach): a circle, a capsule or a convex polygon (a regular polygon of
    3-6 sides, stretched), at most 0.6 across."""
    kind = draw(st.sampled_from(["circle", "capsule", "polygon"]))
    size = draw(engine_floats(0.05, 0.3))
    if kind == "circle":
        return [(0.0, 0.0)], size, size
    if kind == "capsule":
        r = draw(engine_floats(0.02, size / 2))
        return [(-size + r, 0.0), (size - r, 0.0)], r, size
    n = draw(st.integers(3, 6))
    stretch = draw(engine_floats(0.5, 1.0))
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
            x = draw(engine_floats(-HALF + reach + 0.01, HALF - reach - 0.01))
            y = draw(engine_floats(-HALF + reach + 0.01, HALF - reach - 0.01))
            if all(math.hypot(x - a, y - b) > reach + r + 0.01 for a, b, r in placed):
                break
        else:
            continue
        placed.append((x, y, reach))
        speed = draw(st.sampled_from([1.0, 30.0, 1000.0]))
        heading = draw(engine_floats(0, 2 * math.pi))
        bodies.append(dict(vertices=verts, radius=radius, position=(x, y),
                           angle=draw(engine_floats(0, 2 * math.pi)),
                           velocity=(speed * math.cos(heading), speed * math.sin(heading)),
                           omega=draw(st.sampled_from([0.0, 0.0, 3.0, -40.0])),
                           restitution=draw(st.sampled_from([1.0, 0.9, 0.5]))))
    gravity = draw(st.sampled_from([(0.0, 0.0), (0.0, -9.81)]))
    checkpoints = sorted(draw(st.lists(engine_floats(0.001, 1.0), min_size=1, max_size=4)))
    return gravity, bodies, checkpoints


WALLS = [((-HALF, -HALF), (HALF, -HALF)), ((HALF, -HALF), (HALF, HALF)),
         ((HALF, HALF), (-HALF, HALF)), ((-HALF, HALF), (-HALF, -HALF))]
T_C = 1e-3   # the rest rule's contact time (docs/engine.md, defaults)
IMPACT = 1.0      # collisions checked exactly: impacts at least this fast (not rest chatter) ...
MAX_CHECKS = 400  # ... up to this many a world (a settling pile has tens of thousands)


def run_world(World, world) -> dict:
    """Build and run one drawn world; raise AssertionError at the first wrong state. Checked:
    at every impact (up to MAX_CHECKS), its two bodies against each other and the box (within
    TOL, or the contact solver's slop for a body it holds or put to sleep); at each
    checkpoint, every pair; and the energy against its documented bound (it never rises,
    but for the rest rule's minimum parting speeds: at most m (a_n t_c / 2)^2 / 2 for each
    pressing contact, a_n the gap's curvature from gravity and spin, and the contact solver's
    hop, m (|g| h / 2)^2 / 2 per body and tick or soft contact: docs/engine-contact.md).
    Returns counts."""
    gravity, specs, checkpoints = world
    w = World(gravity=gravity)
    for a, b in WALLS:
        w.add_segment(a, b)
    ids = [w.add_body(**spec) for spec in specs]
    reach = {i: max(math.hypot(*v) for v in w.bodies[i].vertices) + w.bodies[i].radius for i in ids}
    lo, hi = Q(-HALF) - TOL, Q(HALF) + TOL
    e0 = w.energy()
    allowance = [0.0]
    counts = {"events": 0, "checks": 0}

    def shape_of(i: int):
        return world_points(w.bodies[i].vertices, w.pose(i)), w.bodies[i].radius

    def held(i: int) -> bool:
        return w.solving(i) or w.asleep(i)

    slop = Q(w.contact_slop)

    def check(k: int, others, when: str) -> None:
        pts, r = shape_of(ids[k])
        s = slop if held(ids[k]) else 0
        # inside the box: its reference point inside, and no wall overlapped by more than the
        # pair's allowance (the walls meet at the corners, so a body that overlaps none and has
        # a point inside is inside; a held body may sit the slop deep in a wall's end point,
        # which at a tilted corner puts a vertex past both wall lines by more than the slop)
        x0, y0 = w.pose(ids[k])[:2]
        assert lo <= Q(x0) <= hi and lo <= Q(y0) <= hi, \
            f"body {k} left the box {when}: its position ({x0}, {y0})"
        for a, b in WALLS:
            assert not too_close(pts, r, [(Q(a[0]), Q(a[1])), (Q(b[0]), Q(b[1]))], 0.0, TOL + s), \
                f"body {k} overlaps the wall {a}-{b} {when}: {w.pose(ids[k])} r = {r}"
        for j in others:
            if j != k:
                pair = TOL + (slop if held(ids[k]) and held(ids[j]) else 0)
                assert not too_close(pts, r, *shape_of(ids[j]), pair), \
                    f"bodies {k} and {j} overlap {when}: {w.pose(ids[k])} {w.pose(ids[j])}"
        counts["checks"] += 1

    def on_event(world, ev) -> None:
        counts["events"] += 1
        g = math.hypot(*gravity)
        pair = [ids.index(body) for body in (ev.a, ev.b) if body in reach]
        for body in (ev.a, ev.b):
            if body in reach:
                if abs(ev.speed) >= IMPACT and counts["checks"] < MAX_CHECKS:
                    check(ids.index(body), pair, f"at the collision at t = {ev.time}")
                m = w.bodies[body].mass
                a_n = g + w.velocity(body)[2] ** 2 * reach[body]
                allowance[0] += m * (a_n * T_C / 2) ** 2 / 2 + m * (g * STEP / 2) ** 2 / 2

    w.on_collision(on_event)
    for t in checkpoints:
        try:
            w.step_to(t)
        except EngineError as exc:   # a named condition is allowed; a wrong place is not
            assert "stuck" in str(exc) or "events" in str(exc), exc
            return counts
        for k in range(len(ids)):
            check(k, range(k + 1, len(ids)), f"at t = {t}")
        e = w.energy()
        hops = w.stats()["solver_ticks"] * sum(w.bodies[i].mass for i in ids) \
            * (math.hypot(*gravity) * STEP / 2) ** 2 / 2
        assert e <= e0 + 1e-9 * abs(e0) + allowance[0] + hops + 1e-12, \
            f"energy rose from {e0} to {e} by t = {t} (allowed {allowance[0]})"
    return counts


# Found by this fuzz (issue 33): bodies 0 and 1 met 1e-5 m deep at t = 0.486 -- the rhombus
# had left the contact solver and kept its slop against the spinning capsule's far side
# (predict.c feature_slop; test_a_body_that_left_the_solver_keeps_no_slop_it_had_not is the
# minimal world).
LEFT_THE_SOLVER = (
    (0.0, -9.81),
    [{'vertices': [(-0.2057841062816659, 0.0), (0.2057841062816659, 0.0)], 'radius': 0.09421589371833403,
      'position': (7.844506395975506e-67, -1.192092896e-07), 'angle': 1.5526519732095546e-255,
      'velocity': (845.2012800839059, -534.4481229684756), 'omega': -40.0, 'restitution': 0.9},
     {'vertices': [(0.2, 0.0), (1.2246467991473533e-17, 0.1538221519853727), (-0.2, 1.8837780606684434e-17),
                   (-3.6739403974420595e-17, -0.1538221519853727)], 'radius': 0.0,
      'position': (-3.4652915676288307, 8.006883088384901e-209), 'angle': 1.8650237575781126,
      'velocity': (0.9999999999999982, 5.960464477539059e-08), 'omega': 3.0, 'restitution': 0.5},
     {'vertices': [(0.0, 0.0)], 'radius': 0.26599975074972965,
      'position': (-2.5853651572339484, -1.5210805130507405), 'angle': 3.413251745744499,
      'velocity': (24.29679505155101, 17.59732224581133), 'omega': -40.0, 'restitution': 1.0},
     {'vertices': [(-0.09704782750908969, 0.0), (0.09704782750908969, 0.0)], 'radius': 0.052952172490910304,
      'position': (1.6642354793133416, 0.8614420243903691), 'angle': 4.769532688951446,
      'velocity': (0.2569418993032532, 0.9664268520599151), 'omega': 0.0, 'restitution': 0.5},
     {'vertices': [(-0.15992348362055792, 0.0), (0.15992348362055792, 0.0)], 'radius': 0.0897301223355632,
      'position': (-2.540605513278925e-178, -2.23157379669911), 'angle': 1.2741760182006059,
      'velocity': (920.7872075813343, -390.0652744792448), 'omega': 0.0, 'restitution': 0.9},
     {'vertices': [(-0.119922538862263, 0.0), (0.119922538862263, 0.0)], 'radius': 0.119922538862263,
      'position': (3.839931060925747e-225, 4.228201029396537), 'angle': 4.127988307077844,
      'velocity': (-0.8465658951347372, -0.5322839328729744), 'omega': -40.0, 'restitution': 0.5}],
    [0.2705272904655855, 0.7009123627274464, 1.0])


# derandomized: the same 25 worlds each run (CI must not flicker); the long run
# (tests/engine/tunnelling_long.py, `make fuzz`, --seed) draws new ones
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow],
          derandomize=True, database=None,
          phases=(Phase.explicit, Phase.reuse, Phase.generate))   # (a failure prints its world)
@given(world=worlds())
@example(world=LEFT_THE_SOLVER)
def test_nothing_tunnels_in_random_worlds(engine, world):
    run_world(engine.World, world)


def test_the_exact_checks_see_an_overlap_and_an_escape():
    """The oracle itself: a square and a circle 1e-3 into it overlap; 1e-3 apart they do not;
    a segment's end point and a capsule are measured from the segment, not its ends only."""
    square = world_points([(-1, -1), (1, -1), (1, 1), (-1, 1)], (0.0, 0.0, 0.0))
    assert too_close(square, 0.0, world_points([(0, 0)], (1.499, 0.0, 0.0)), 0.5)
    assert not too_close(square, 0.0, world_points([(0, 0)], (1.501, 0.0, 0.0)), 0.5)
    seg = world_points([(-1, 0), (1, 0)], (0.0, 0.0, 0.0))
    assert too_close(seg, 0.1, world_points([(0, 0)], (0.0, 0.15, 0.0)), 0.1)
    assert not too_close(seg, 0.1, world_points([(0, 0)], (0.0, 0.25, 0.0)), 0.1)
    # two capsules whose cores cross, every end point 1 m from the other core
    upright = world_points([(-1, 0), (1, 0)], (0.0, 0.0, math.pi / 2))
    assert too_close(seg, 0.1, upright, 0.1)
    assert not too_close(seg, 0.1, world_points([(-1, 0), (1, 0)], (0.0, 1.21, math.pi / 2)), 0.1)
    # polygons (no radius): a small square inside a big one, and two squares 1e-3 deep
    small = world_points([(-0.1, -0.1), (0.1, -0.1), (0.1, 0.1), (-0.1, 0.1)], (0.0, 0.0, 0.0))
    assert too_close(square, 0.0, small, 0.0)
    assert too_close(square, 0.0, world_points([(-1, -1), (1, -1), (1, 1), (-1, 1)], (1.999, 0.5, 0.0)), 0.0)
    assert not too_close(square, 0.0, world_points([(-1, -1), (1, -1), (1, 1), (-1, 1)], (2.0, 0.5, 0.0)), 0.0)
    assert not too_close(square, 0.0, world_points([(-1, -1), (1, -1), (1, 1), (-1, 1)], (1.9999999, 0.5, 0.0)), 0.0)


# Found by the long run (tests/engine/tunnelling_long.py, seed 0, its first world): a capsule
# driven to 5067 rad/s by hits from a 1000 m/s ball met a circle 3.8 mm deep (16 microseconds
# late). Two bodies alone reproduce it. The rotating predictor's inside walk called a point 2.5e-7
# inside the capsule's edge line a root, and the contact after it was lost (engine/src/predict.c,
# solve_rotating; tests/engine/test_spinning_contact.py is the property).
SPINNING_CAPSULE = {'vertices': ((-0.0452693786105278, 0.0), (0.0452693786105278, 0.0)),
                    'radius': 0.03741078899513627, 'position': (2.859363187034921, -3.3939069093669936),
                    'angle': 15.633394090624263, 'velocity': (-767.2989822877518, -161.84632896265157),
                    'omega': 5067.279136350295, 'mass': 0.011171122508545704,
                    'inertia': 2.619598673306495e-05}
DISC = {'vertices': ((0.0, 0.0),), 'radius': 0.17293368362153017,
        'position': (0.9899791244293512, -3.3599439822504875), 'angle': -1.7344440784610233,
        'velocity': (-86.93119312535697, -105.42592670094143), 'omega': -39.99999999999912,
        'mass': 0.09395265503517496, 'inertia': 0.0014048768190987701}


def test_a_fast_spinning_capsule_is_met_at_the_touch(engine):
    w = engine.World()
    a, b = w.add_body(**SPINNING_CAPSULE), w.add_body(**DISC)
    depth: list[float] = []

    def at_contact(world, ev) -> None:
        p = world_points(w.bodies[a].vertices, w.pose(a))
        c = world_points(w.bodies[b].vertices, w.pose(b))[0]
        gap = math.sqrt(float(dist2_point_segment(c, p[0], p[1]))) - SPINNING_CAPSULE["radius"] - DISC["radius"]
        depth.append(gap)

    w.on_collision(at_contact)
    w.step_to(0.01)
    assert depth and depth[0] >= -1e-6, depth


# The fuzz's world above, made small (issue 33): a body the contact solver let go keeps the
# overlap it has then (the solver's slop, up to 1e-5 m), so that it does not sink further. It
# kept it for every feature whose gap was negative -- a point behind an edge's line, which the
# far corners of two bodies apart always are -- so a box set flying off the floor, landing on
# a block's top (its corners had been below that line), met it 1e-5 m deep, 2.5 microseconds
# late. predict.c feature_slop now keeps only an overlap the shapes have.
SQUARE = [(-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2)]
BLOCK = [(1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0)]


def test_a_body_that_left_the_solver_keeps_no_slop_it_had_not(engine):
    g, v = 9.81, (1.5, 6.0)
    w = engine.World(gravity=(0.0, -g))
    w.add_segment((-5.0, 0.0), (5.0, 0.0))
    box = w.add_polygon(SQUARE, position=(0.0, 0.5), restitution=0.5)
    block = w.add_polygon(BLOCK, kind="static")
    w.step_to(0.5)
    assert w.solving(box)   # the edit below lets it go: it flies with the solver's slop allowed
    t0, pose = w.time, w.pose(box)
    w.set_velocity(box, v)
    # the oracle: the box flies without turning; its lowest corner lands on the block's top
    # (y = 1) at the later root of y0 + vy t - g t^2 / 2 = 1, inside [1, 2]
    corner = min(world_points(w.bodies[box].vertices, pose), key=lambda q: q[1])
    y0 = float(corner[1])
    t_land = t0 + (v[1] + math.sqrt(v[1] ** 2 + 2 * g * (y0 - 1.0))) / g
    assert 1.0 < float(corner[0]) + v[0] * (t_land - t0) < 2.0
    hits: list[tuple[float, bool]] = []

    def on_hit(world, ev) -> None:
        if {ev.a, ev.b} == {box, block}:
            deep = too_close(world_points(w.bodies[box].vertices, w.pose(box)), 0.0,
                             world_points(w.bodies[block].vertices, w.pose(block)), 0.0,
                             Q(1, 10**8))
            hits.append((ev.time, deep))

    w.on_collision(on_hit)
    w.step_to(t_land + 0.01)
    assert hits, "the box never met the block"
    t, deep = hits[0]
    assert not deep, f"the box met the block more than 1e-8 m deep at t = {t}"
    assert abs(t - t_land) <= 1e-9, (t, t_land)


# Found by the long run (tests/engine/tunnelling_long.py --count 500 --seed 0, world 212; the
# same before issue 33's fix): a pentagon the contact solver holds in the box's corner pokes
# 1.25e-5 m below the floor's line, beyond the slop (1e-5 m) that run_world allows a held body.
HELD_IN_A_CORNER = ((0.0, -9.81),
 [{'vertices': [(0.09748205466850365, 0.0), (5.969054311204515e-18, 0.06298920338230832),
                (-0.09748205466850365, 7.713952630298552e-18),
                (-1.7907162933613544e-17, -0.06298920338230832)],
   'radius': 0.0,
   'position': (-2.634467025660529, 3.4956857338939553),
   'angle': 0.12375463011086285,
   'velocity': (-945.7480206039164, -324.901033429834),
   'omega': 0.0,
   'restitution': 0.9},
  {'vertices': [(0.05, 0.0), (-0.02499999999999999, 0.02611448147621532),
                (-0.025000000000000022, -0.02611448147621531)],
   'radius': 0.0,
   'position': (3.862684342929758, 1.401298464324817e-45),
   'angle': 3.078541625934469,
   'velocity': (0.38701706491093674, -0.9220725521713158),
   'omega': 0.0,
   'restitution': 0.5},
  {'vertices': [(-0.14069291391483602, 0.0), (0.14069291391483602, 0.0)],
   'radius': 0.11110586086921752,
   'position': (-1.175494351e-38, -0.5394993586486603),
   'angle': 0.0,
   'velocity': (-0.9980121410487648, -0.0630219510905554),
   'omega': 0.0,
   'restitution': 0.5},
  {'vertices': [(0.0, 0.0)],
   'radius': 0.23184192770470824,
   'position': (0.12713410682458992, 3.3495201321217207),
   'angle': 2.9144361464641912,
   'velocity': (1000.0, 9.844219208616747e-215),
   'omega': 3.0,
   'restitution': 0.9},
  {'vertices': [(0.17629020427234998, 0.0), (0.05447666906198711, 0.08903453761622626),
                (-0.14262177119816208, 0.05502637041945888),
                (-0.14262177119816213, -0.05502637041945886),
                (0.054476669061987074, -0.08903453761622626)],
   'radius': 0.0,
   'position': (5.960464477539063e-08, 4.490391667898846),
   'angle': 5.731819682140385,
   'velocity': (-924.95441786649, -380.078051022764),
   'omega': 0.0,
   'restitution': 0.5}],
 [0.08052297957995569, 1.0])


def test_a_body_held_in_a_corner_stays_within_the_slop_of_each_wall(engine):
    """Not tunnelling: each wall's overlap with the pentagon (exact separating axes) is within
    the slop, 1.0000e-5 m against the floor, 6.7e-6 m against the left wall. But its vertex lies
    beyond the floor's end (x < -5), so the floor's line is no contact there (on_edge); the
    floor's end point against the pentagon's edge is, and the slop lets that point sit 1e-5 m
    inside the edge, which lets the vertex sit 1.25e-5 m below y = -5 at the tilt. run_world
    checked a held body per coordinate (it failed here, and in about 1 of 600 drawn worlds);
    it now measures each wall's overlap, the engine's promise for a pair (docs/engine.md)."""
    run_world(engine.World, HELD_IN_A_CORNER)


# Drawn by the long run (`python -m tests.engine.tunnelling_long --count 300 --seed 2`, world 294)
# once walls were checked by overlap: the triangle (spec 2), struck by the rhombus at 1000 m/s,
# reaches the box's corner (5, -5); at its collision at t = 0.0534772 a vertex is 1.52e-5 m past
# the right wall's line (exact separating axes), beyond the tolerance and the solver's slop.
CORNER_STRUCK = ((0.0, -9.81), [
    {'vertices': [(-0.04046637028744522, 0.0), (0.04046637028744522, 0.0)],
     'radius': 0.024713121519477074, 'position': (2.6234552963908504, -3.412611340392095),
     'angle': 2.3973802386560643, 'velocity': (30.0, 3.1692920895214016e-50), 'omega': 0.0,
     'restitution': 1.0},
    {'vertices': [(0.0, 0.0)], 'radius': 0.05,
     'position': (5.949241053843218e-196, -3.0178080412486725), 'angle': 2.2250738585e-313,
     'velocity': (0.8548698046927414, 0.5188425744140454), 'omega': -40.0, 'restitution': 1.0},
    {'vertices': [(0.07193537518221889, 0.0), (-0.03596768759110943, 0.046246226649175805),
                  (-0.03596768759110948, -0.046246226649175784)],
     'radius': 0.0, 'position': (2.685268320358972, 1.9762718878721008),
     'angle': 6.283185307179586, 'velocity': (0.09027250822731751, 0.9959171021015498),
     'omega': 3.0, 'restitution': 0.5},
    {'vertices': [(-0.03046486402200158, 0.0), (0.03046486402200158, 0.0)],
     'radius': 0.027602159047169377, 'position': (1.9175835179667014e-222, 2.8388013595556156),
     'angle': 5.5877507849311865, 'velocity': (19.74612547853689, 22.585183828914836),
     'omega': 3.0, 'restitution': 0.5},
    {'vertices': [(0.0, 0.0)], 'radius': 0.1992226516337069,
     'position': (3.8600885342089244, -6.103515625e-05), 'angle': 1.516613311280849,
     'velocity': (-0.19713264137730116, -0.9803768263803507), 'omega': -40.0,
     'restitution': 1.0},
    {'vertices': [(0.2590059086950643, 0.0), (1.5859537852183106e-17, 0.24938441278428444),
                  (-0.2590059086950643, 3.054078228735162e-17),
                  (-4.7578613556549314e-17, -0.24938441278428444)],
     'radius': 0.0, 'position': (0.36004936350582817, 0.7996952253661718),
     'angle': 2.6008806791746686, 'velocity': (-879.5339924972435, 475.8360600478475),
     'omega': -40.0, 'restitution': 0.9},
    {'vertices': [(0.0, 0.0)], 'radius': 0.08812820518576472,
     'position': (9.585097921405113e-178, 0.5), 'angle': 5.814807234001405,
     'velocity': (0.4810807792923089, 0.8766762708066785), 'omega': 3.0, 'restitution': 0.5}],
    [0.14262172962958897, 0.99999])


def test_a_body_struck_into_a_corner_stays_out_of_the_walls(engine):
    """A world nobody designed: the triangle, spinning at 15,700 rad/s after the rhombus's
    strike, chattered against the ball (spec 4) in a Zeno burst, and the burst rule made that
    a soft contact; the soft response parted the pair at the gap's curvature times h / 2,
    with the spin's curvature (omega^2 r ~ 1.7e7 m/s^2) 91,000 m/s, and the triangle hit the
    corner (5, -5) 1.52e-5 m past the right wall's line. A contact whose rotation curves it in
    faster than a soft contact closes is no sustained contact now (response.c, soft_contact):
    an exact impact, as without the solver (issue 33)."""
    run_world(engine.World, CORNER_STRUCK)


def test_a_fast_spinning_edge_on_a_held_ball_is_parted_by_the_rest_rule(engine):
    """The corner world's cause, alone (issue 33): a triangle spinning at 15,000 rad/s whose
    edge faces a static ball 1e-12 m away touches it at once with no approach; its rotation
    curves the edge into the ball at a_n = omega^2 D (D the centres' distance, the gap being
    D cos(omega t) - e - R). A soft contact parted it at a_n h / 2 (64 km/s, h = 1/240); an
    exact contact parts at a_n t_c / 2 at most, the rest rule's bound (docs/engine.md): the
    kinetic energy gained is at most m (a_n t_c / 2)^2 / 2 (closed form, t_c = 1e-3)."""
    verts = CORNER_STRUCK[1][2]['vertices']
    e = -verts[1][0]                    # the left edge's distance from the centre
    w = engine.World(gravity=(0.0, -9.81))
    w.add_body([(0.0, 0.0)], radius=0.1, kind="static")
    omega = 15000.0
    tri = w.add_body(verts, position=(0.1 + e + 1e-12, 0.0), angle=0.0, omega=omega)
    e0, m = w.energy(), w.bodies[tri].mass
    w.step_to(1e-6)
    a_n = omega ** 2 * (0.1 + e)
    assert w.energy() - e0 <= m * (a_n * T_C / 2) ** 2 / 2 * (1 + 1e-6) + 1e-9
