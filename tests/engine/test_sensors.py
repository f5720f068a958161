"""Sensors report enter ("sensor") and leave ("sensor_leave") at their exact times (issue 35).

Hand cases have closed forms; the property test checks random straight-line and rotating
motions of circles, boxes and capsules through static, kinematic and dynamic sensors against an
independent oracle: the signed distance between the two shapes (separating axes of the cores
when they overlap, the cores' distance when apart, minus the radii), its sign changes found on a
grid in floats and bisected in mpmath at 40 digits. Enter and leave must alternate, match the
oracle's crossings one for one, and agree in time to 1e-9."""

from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from .scenes import engine_floats

BOX = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]


def _kinds(events):
    return [(e.kind, e.time) for e in events if e.kind in ("sensor", "sensor_leave")]


def test_circle_through_circle(engine) -> None:
    """|x| = 1.25 with x = t - 3: enter at 1.75, leave at 4.25, nothing else."""
    w = engine.World()
    s = w.add_circle((0.0, 0.0), 1.0, kind="static", sensor=True)
    b = w.add_circle((-3.0, 0.0), 0.25, velocity=(1.0, 0.0))
    events = w.step_to(8.0)
    assert [(e.kind, e.time) for e in events] == [("sensor", 1.75), ("sensor_leave", 4.25)]
    assert {events[1].a, events[1].b} == {s, b}
    assert w.velocity(b)[0] == 1.0


def test_box_through_box(engine) -> None:
    """A 0.4 box through a 2 box along x: faces meet at x + 0.2 = -1 and part at x - 0.2 = 1."""
    w = engine.World()
    w.add_polygon(BOX, kind="static", sensor=True)
    w.add_polygon([(-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2)], position=(-3.0, 0.3),
                  velocity=(1.0, 0.0))
    assert _kinds(w.step_to(8.0)) == [("sensor", pytest.approx(1.8, rel=1e-14)),
                                       ("sensor_leave", pytest.approx(4.2, rel=1e-14))]


def test_rotating_box_straddling_an_edge_is_one_stay(engine) -> None:
    """A spinning box crossing the sensor's edge: its corners cross the edge again and again
    while it straddles it; those are no events. One enter, one leave, each where the oracle
    says the shapes first and last touch."""
    w = engine.World()
    w.add_polygon(BOX, kind="static", sensor=True)
    small = [(-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2)]
    w.add_polygon(small, position=(-3.0, 0.3), velocity=(1.0, 0.0), omega=1.0)
    got = _kinds(w.step_to(8.0))
    want = _crossings(Moving(small, 0.0, (-3.0, 0.3), (1.0, 0.0), 0.0, 1.0),
                      Moving(BOX, 0.0, (0.0, 0.0), (0.0, 0.0), 0.0, 0.0), 8.0)
    assert [k for k, _ in got] == ["sensor", "sensor_leave"]
    assert [t for _, t in got] == pytest.approx([t for _, t in want], rel=1e-10)


def test_capsule_through_segment_sensor(engine) -> None:
    """A ball through a two-sided segment sensor (a line across its path): touches it at
    |x| = 0.25 on either side."""
    w = engine.World()
    w.add_segment((0.0, -1.0), (0.0, 1.0), sensor=True)
    w.add_circle((-1.0, 0.0), 0.25, velocity=(0.5, 0.0))
    assert _kinds(w.step_to(5.0)) == [("sensor", 1.5), ("sensor_leave", 2.5)]


def test_moving_sensor_passes_a_ball(engine) -> None:
    """A kinematic sensor sweeping over a ball at rest: enter and leave both reported."""
    w = engine.World()
    w.add_circle((-4.0, 0.0), 1.0, kind="kinematic", velocity=(2.0, 0.0), sensor=True)
    w.add_circle((0.0, 0.0), 0.5)
    assert _kinds(w.step_to(5.0)) == [("sensor", 1.25), ("sensor_leave", 2.75)]


def test_removed_inside_reports_no_leave(engine) -> None:
    """Removing either body while they overlap ends the pair without a leave (documented)."""
    w = engine.World()
    s = w.add_circle((0.0, 0.0), 1.0, kind="static", sensor=True)
    b = w.add_circle((-3.0, 0.0), 0.25, velocity=(1.0, 0.0))
    w.on_collision(lambda world, ev: world.remove(b) if ev.kind == "sensor" else None)
    assert _kinds(w.step_to(8.0)) == [("sensor", 1.75)]
    assert w.bodies[s].alive


def test_moved_out_leaves_at_once(engine) -> None:
    """set_pose out of a sensor's overlap is a leave now; the next pass enters again."""
    w = engine.World()
    s = w.add_circle((0.0, 0.0), 1.0, kind="static", sensor=True)
    b = w.add_circle((-3.0, 0.0), 0.25, velocity=(1.0, 0.0))
    assert _kinds(w.step_to(2.0)) == [("sensor", 1.75)]
    w.set_pose(b, (-4.0, 0.0))
    assert _kinds(w.step_to(6.0)) == [("sensor_leave", 2.0), ("sensor", 4.75)]


def test_added_inside_enters_at_once(engine) -> None:
    """A body made inside a sensor (or a sensor made over a body) enters it when added."""
    w = engine.World()
    w.add_circle((0.0, 0.0), 1.0, kind="static", sensor=True)
    w.add_circle((0.5, 0.0), 0.25, velocity=(1.0, 0.0))
    assert _kinds(w.step_to(3.0)) == [("sensor", 0.0), ("sensor_leave", 0.75)]
    b = w.add_circle((5.0, 5.0), 0.25)
    w.add_circle((5.0, 5.5), 1.0, kind="kinematic", velocity=(0.0, 1.0), sensor=True)
    assert _kinds(w.step_to(5.0)) == [("sensor", 3.0), ("sensor_leave", 3.75)]
    assert w.velocity(b)[:2] == (0.0, 0.0)


def test_snapshot_inside_keeps_the_leave(engine) -> None:
    """A world saved while a body is inside a sensor reports the same leave after restore."""
    import copy
    w = engine.World()
    w.add_circle((0.0, 0.0), 1.0, kind="static", sensor=True)
    w.add_circle((-3.0, 0.0), 0.25, velocity=(1.0, 0.0))
    assert _kinds(w.step_to(3.0)) == [("sensor", 1.75)]
    twin = copy.deepcopy(w)
    assert _kinds(twin.step_to(8.0)) == _kinds(w.step_to(8.0)) == [("sensor_leave", 4.25)]


def test_leave_goes_to_the_separate_handler(engine) -> None:
    """pymunk's order for sensors: begin on enter, separate on leave."""
    w = engine.World()
    w.add_circle((0.0, 0.0), 1.0, kind="static", sensor=True, collision_type=2)
    w.add_circle((-3.0, 0.0), 0.25, velocity=(1.0, 0.0), collision_type=1)
    log = []
    h = w.collision_handler(1, 2)
    h.begin = lambda world, ev: log.append(("begin", ev.time))
    h.separate = lambda world, ev: log.append(("separate", ev.time))
    w.step_to(8.0)
    assert log == [("begin", 1.75), ("separate", 4.25)]


# ------------------------------------------------------------------------------------------ #
# The oracle                                                                                   #
# ------------------------------------------------------------------------------------------ #

@dataclass(frozen=True)
class Moving:
    """A shape (body-frame vertices and a radius) at p + v t, turned by th + w t."""
    verts: list
    radius: float
    p: tuple
    v: tuple
    th: float
    w: float

    def world(self, t, M):
        c, s = M.cos(self.th + self.w * t), M.sin(self.th + self.w * t)
        x, y = self.p[0] + self.v[0] * t, self.p[1] + self.v[1] * t
        return [(x + c * a - s * b, y + s * a + c * b) for a, b in self.verts]


class _Float:
    cos, sin, sqrt = staticmethod(math.cos), staticmethod(math.sin), staticmethod(math.sqrt)


def _edges(P):
    n = len(P)
    return [(P[k], P[(k + 1) % n]) for k in range(n if n >= 3 else n - 1)]


def _seg_dist(c, a, b, M):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L2 = dx * dx + dy * dy
    u = ((c[0] - a[0]) * dx + (c[1] - a[1]) * dy) / L2
    u = min(max(u, 0), 1)
    ex, ey = c[0] - a[0] - u * dx, c[1] - a[1] - u * dy
    return M.sqrt(ex * ex + ey * ey)


def _separation(P, Q):
    """The separating axis theorem over the edge normals of both cores (both senses)."""
    best = None
    for S in (P, Q):
        for a, b in _edges(S):
            n = (b[1] - a[1], a[0] - b[0])
            pa = [x * n[0] + y * n[1] for x, y in P]
            pq = [x * n[0] + y * n[1] for x, y in Q]
            L = (n[0] ** 2 + n[1] ** 2) ** 0.5
            s = max(min(pq) - max(pa), min(pa) - max(pq)) / L
            best = s if best is None else max(best, s)
    return best


def _signed_gap(A: Moving, B: Moving, t, M) -> float:
    P, Q = A.world(t, M), B.world(t, M)
    sep = _separation(P, Q)
    if sep is not None and sep <= 0:   # the cores overlap (or touch): minus their depth
        core = sep
    else:
        ds = [M.sqrt((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2) for p in P for q in Q]
        ds += [_seg_dist(p, a, b, M) for p in P for a, b in _edges(Q)]
        ds += [_seg_dist(q, a, b, M) for q in Q for a, b in _edges(P)]
        core = min(ds)
    return core - A.radius - B.radius


def _crossings(A: Moving, B: Moving, T: float, n: int = 4000):
    """[("sensor" | "sensor_leave", time)]: sign changes of the signed gap on (0, T], bisected
    in mpmath; None when the motion grazes (a sign change too close to call)."""
    ts = [T * k / n for k in range(n + 1)]
    g = [_signed_gap(A, B, t, _Float) for t in ts]
    if min(abs(x) for x in g) < 1e-6:
        return None
    for k in range(1, n):  # a dip or peak near 0 between samples: too close to call
        if (g[k] - g[k - 1]) * (g[k + 1] - g[k]) < 0 and abs(g[k]) < 2e-3:
            return None
    out = []
    with mpmath.workdps(40):
        Am = Moving(A.verts, mpmath.mpf(A.radius), tuple(map(mpmath.mpf, A.p)),
                    tuple(map(mpmath.mpf, A.v)), mpmath.mpf(A.th), mpmath.mpf(A.w))
        Bm = Moving(B.verts, mpmath.mpf(B.radius), tuple(map(mpmath.mpf, B.p)),
                    tuple(map(mpmath.mpf, B.v)), mpmath.mpf(B.th), mpmath.mpf(B.w))
        for k in range(n):
            if (g[k] > 0) != (g[k + 1] > 0):
                lo, hi = mpmath.mpf(ts[k]), mpmath.mpf(ts[k + 1])
                glo = _signed_gap(Am, Bm, lo, mpmath)
                for _ in range(64):
                    m = (lo + hi) / 2
                    gm = _signed_gap(Am, Bm, m, mpmath)
                    if (gm > 0) == (glo > 0):
                        lo, glo = m, gm
                    else:
                        hi = m
                out.append(("sensor" if g[k] > 0 else "sensor_leave", float((lo + hi) / 2)))
    return out


SHAPES = {
    "circle": lambda s: ([(0.0, 0.0)], 0.5 * s),
    "box": lambda s: ([(-0.5 * s, -0.3 * s), (0.5 * s, -0.3 * s), (0.5 * s, 0.3 * s),
                       (-0.5 * s, 0.3 * s)], 0.0),
    "capsule": lambda s: ([(-0.4 * s, 0.0), (0.4 * s, 0.0)], 0.2 * s),
}


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.filter_too_much,
                                                                  HealthCheck.too_slow])
@given(body=st.sampled_from(sorted(SHAPES)), sensor=st.sampled_from(sorted(SHAPES)),
       sensor_kind=st.sampled_from(["static", "kinematic", "dynamic"]),
       size=engine_floats(0.2, 1.0), ssize=engine_floats(1.0, 3.0),
       y0=engine_floats(-1.2, 1.2), vx=engine_floats(0.5, 2.0), vy=engine_floats(-0.3, 0.3),
       th=engine_floats(-3.0, 3.0), w=st.sampled_from([0.0, 0.0, 0.7, -1.3, 2.5]),
       sv=engine_floats(-0.3, 0.3), sth=engine_floats(-1.0, 1.0), sw=st.sampled_from([0.0, 0.0, 0.5, -0.8]))
def test_enter_and_leave_match_the_oracle(engine, body, sensor, sensor_kind, size, ssize, y0,
                                          vx, vy, th, w, sv, sth, sw) -> None:
    T = 8.0
    bv, br = SHAPES[body](size)
    sv_, sr = SHAPES[sensor](ssize)
    moving = sensor_kind != "static"
    A = Moving(bv, br, (-5.0, y0), (vx, vy), th, w)
    B = Moving(sv_, sr, (0.0, 0.0), (sv, 0.0) if moving else (0.0, 0.0), sth,
               sw if moving else 0.0)
    assume(_signed_gap(A, B, 0.0, _Float) > 0.05)
    want = _crossings(A, B, T)
    assume(want is not None)
    wd = engine.World()
    wd.add_body(sv_, radius=sr, position=B.p, angle=B.th, velocity=B.v, omega=B.w,
                kind=sensor_kind, sensor=True)
    wd.add_body(bv, radius=br, position=A.p, angle=A.th, velocity=A.v, omega=A.w)
    got = _kinds(wd.step_to(T))
    assert [k for k, _ in got] == [k for k, _ in want], (got, want)
    for (_, tg), (_, tw) in zip(got, want):
        assert tg == pytest.approx(tw, rel=1e-9, abs=1e-9)
    kinds = [k for k, _ in got]
    assert kinds[::2] == ["sensor"] * len(kinds[::2]) and "sensor" not in kinds[1::2]


def test_a_busy_room_keeps_every_pair_straight(engine) -> None:
    """Thirty balls and spinning boxes bouncing in a room with five sensor zones: per pair,
    enters and leaves alternate, and after every second the pairs reported inside are exactly
    those the oracle finds overlapping (nothing missed, nothing left over)."""
    import random
    r = random.Random(7)
    w = engine.World()
    for a, b in [((-10, -10), (10, -10)), ((10, -10), (10, 10)), ((10, 10), (-10, 10)),
                 ((-10, 10), (-10, -10))]:
        w.add_segment(a, b)
    zones = [w.add_polygon([(-2, -2), (2, -2), (2, 2), (-2, 2)], position=c, kind="static",
                           sensor=True) for c in [(-5, -5), (5, -5), (-5, 5), (5, 5), (0, 0)]]
    for k in range(30):
        p, v = (-9 + (k % 10) * 2, -8 + (k // 10) * 2), (r.uniform(-2, 2), r.uniform(-2, 2))
        if k % 2:
            w.add_circle(p, 0.3, velocity=v)
        else:
            w.add_polygon([(-.3, -.3), (.3, -.3), (.3, .3), (-.3, .3)], position=p, velocity=v,
                          omega=r.uniform(-2, 2))
    inside: dict = {}
    count = 0
    for t in range(1, 11):
        for e in w.step_to(float(t)):
            if e.kind in ("sensor", "sensor_leave"):
                key = (min(e.a, e.b), max(e.a, e.b))
                assert inside.get(key, False) == (e.kind == "sensor_leave"), (e, t)
                inside[key] = e.kind == "sensor"
                count += 1

        def now(i):
            x, y, th = w.pose(i)
            return Moving(list(w.bodies[i].vertices), w.bodies[i].radius, (x, y), (0, 0), th, 0)
        for z in zones:
            for b in w.bodies:
                if b.kind == "dynamic":
                    g = _signed_gap(now(b.id), now(z), 0.0, _Float)
                    if abs(g) > 1e-9:
                        assert (g < 0) == inside.get((min(b.id, z), max(b.id, z)), False), (t, b.id, z, g)
    assert count > 40
