"""Changing bodies at the current time (issue 35, the API games need): removal (also from a
callback), pose, velocity of dynamic and kinematic bodies, acceleration, kind (PGE's
fix/unfix), mass, impulses, timers with cancel, collision filters, either polygon winding,
and the C library's default def and exports. Each expectation is a closed form."""

from __future__ import annotations

import math
import re
import shutil
import subprocess

import pytest

SQUARE = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]


def test_removed_wall_lets_the_ball_through(engine) -> None:
    w = engine.World()
    wall = w.add_segment((2.0, -1.0), (2.0, 1.0))
    ball = w.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0))
    w.step_to(1.0)                       # its contact (t = 1.5) is already predicted
    w.remove(wall)
    assert not w.alive(wall) and not w.bodies[wall].alive
    assert w.step_to(5.0) == []
    assert w.pose(ball) == (5.0, 0.0, 0.0)
    with pytest.raises(engine.EngineError, match="removed"):
        w.remove(wall)


def test_removal_from_a_callback_is_effective_at_once(engine) -> None:
    """A breakout row: each brick hit is removed inside the callback; the ball bounces off it
    (the impulse came first) and the next prediction no longer sees it."""
    w = engine.World()
    bricks = [w.add_polygon(SQUARE, kind="static", position=(3.0 + 2.0 * k, 0.0)) for k in range(3)]
    back = w.add_segment((-4.0, -1.0), (-4.0, 1.0))
    ball = w.add_circle((0.0, 0.0), 0.25, velocity=(1.0, 0.0))

    def hit(world, ev):
        if ev.b in bricks:
            world.remove(ev.b)

    w.on_collision(hit)
    events = w.step_to(30.0)
    # the ball (radius 0.25) meets brick 0 at x = 2.25, the back wall at -3.75, brick 1 at 4.25
    times = [(e.time, e.b) for e in events]
    assert times[0] == (2.25, bricks[0])
    assert times[1] == (pytest.approx(2.25 + 6.0), back)          # 2.5 back to x = -3.75
    assert times[2] == (pytest.approx(8.25 + 8.0), bricks[1])      # through brick 0's place to 4.25
    assert [w.alive(b) for b in bricks] == [False, False, True]
    assert all(e.b != bricks[0] for e in events[1:])


def test_removing_a_moving_body_drops_its_pending_contacts(engine) -> None:
    w = engine.World()
    a = w.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0))
    b = w.add_circle((3.0, 0.0), 0.5, velocity=(-1.0, 0.0))
    c = w.add_circle((10.0, 0.0), 0.5)
    w.step_to(0.5)                       # a and b would meet at t = 1
    w.remove(b)
    events = w.step_to(20.0)
    assert [(e.a, e.b) for e in events] == [(a, c)]
    assert events[0].time == pytest.approx(9.0, rel=1e-14)
    assert w.pose(b) == (2.5, 0.0, 0.0)  # frozen where it was removed


def test_removal_wakes_what_rested_on_it(engine) -> None:
    w = engine.World(gravity=(0.0, -10.0))
    w.add_segment((-5.0, -2.0), (5.0, -2.0))
    shelf = w.add_polygon(SQUARE, kind="static")
    ball = w.add_circle((0.0, 1.0), 0.1, restitution=0.5)
    events = w.step_to(3.0)
    assert any(e.kind == "rest" for e in events) and w.asleep(ball)
    w.remove(shelf)
    w.step_to(5.0)
    assert not w.asleep(ball) or w.pose(ball)[1] == pytest.approx(-1.9, abs=1e-6)
    assert w.pose(ball)[1] < -1.8


def test_steering_a_kinematic_paddle_changes_the_predicted_collision(engine) -> None:
    def run(steer: bool):
        w = engine.World()
        paddle = w.add_polygon([(-1.0, -0.1), (1.0, -0.1), (1.0, 0.1), (-1.0, 0.1)], kind="kinematic")
        ball = w.add_circle((5.0, 3.0), 0.2, velocity=(0.0, -1.0))
        w.step_to(0.5)
        if steer:
            w.set_velocity(paddle, (2.0, 0.0))
        return w, ball, paddle, w.step_to(4.0)

    w, ball, paddle, events = run(False)
    assert events == []
    w, ball, paddle, events = run(True)
    assert [(e.kind, e.a, e.b) for e in events] == [("collision", ball, paddle)]
    assert events[0].time == pytest.approx(2.7, rel=1e-13)       # y = 3 - t reaches 0.1 + 0.2
    assert w.velocity(ball) == pytest.approx((0.0, 1.0, 0.0), abs=1e-12)
    assert w.pose(paddle)[0] == pytest.approx(2.0 * 3.5, rel=1e-14)


def test_set_pose_moves_and_refuses_overlaps(engine) -> None:
    w = engine.World()
    wall = w.add_segment((2.0, -1.0), (2.0, 1.0))
    block = w.add_polygon(SQUARE, kind="static", position=(0.0, 5.0))
    ball = w.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0))
    with pytest.raises(engine.EngineError, match=f"overlap body {block}"):
        w.set_pose(ball, (0.2, 5.0))
    assert w.pose(ball) == (0.0, 0.0, 0.0)
    w.set_pose(ball, (-3.0, 0.0))
    events = w.step_to(10.0)
    assert events[0].time == pytest.approx(4.5, rel=1e-14) and events[0].b == wall
    # a static wall moved: the ball meets it at its new place
    w2 = engine.World()
    wall2 = w2.add_segment((2.0, -1.0), (2.0, 1.0))
    ball2 = w2.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0))
    w2.step_to(1.0)
    w2.set_pose(wall2, (2.0, 0.0))       # its reference point is where its first vertex was
    events = w2.step_to(10.0)
    assert events[0].time == pytest.approx(3.5, rel=1e-14)
    assert w2.pose(ball2)[0] == pytest.approx(3.5 - 6.5, rel=1e-14)


def test_acceleration_is_exact_ballistics(engine) -> None:
    w = engine.World()
    ball = w.add_circle((0.0, 0.0), 0.1, velocity=(1.0, 0.0))
    w.step_to(1.0)
    w.set_acceleration(ball, (0.0, -4.0))
    w.step_to(3.0)
    assert w.pose(ball)[:2] == pytest.approx((3.0, -0.5 * 4.0 * 4.0), rel=1e-15)
    assert w.velocity(ball)[:2] == pytest.approx((1.0, -8.0), rel=1e-15)


def test_acceleration_reads_the_own_gravity(engine) -> None:
    """World.acceleration: add_body's gravity, else the world's, else set_acceleration's;
    a static body keeps it (and falls with it once dynamic), a dynamic one moves with it."""
    w = engine.World(gravity=(0.0, -10.0))
    ball = w.add_circle((0.0, 0.0), 0.1)
    floaty = w.add_circle((5.0, 0.0), 0.1, gravity=(1.0, 2.0))
    wall = w.add_segment((-9.0, -9.0), (9.0, -9.0))
    box = w.add_polygon(SQUARE, kind="static", position=(0.0, 5.0))
    assert [w.acceleration(b) for b in (ball, floaty, wall, box)] == [
        (0.0, -10.0), (1.0, 2.0), (0.0, -10.0), (0.0, -10.0)]
    w.set_acceleration(ball, (3, -4))
    assert w.acceleration(ball) == (3.0, -4.0)
    w.step_to(1.0)
    assert w.velocity(ball)[:2] == (3.0, -4.0)        # it moves with what it reads
    assert w.velocity(box) == (0.0, 0.0, 0.0)         # static: kept, not applied
    w.set_kind(box, "dynamic")
    w.step_to(1.5)
    assert w.velocity(box)[:2] == pytest.approx((0.0, -5.0), rel=1e-15)


def test_unfix_falls_and_lands_then_fix_stops(engine) -> None:
    """PGE's unfix: a static box becomes dynamic, falls with the world's gravity and lands at
    sqrt(2 h / g); fix makes it static again."""
    g = 10.0
    w = engine.World(gravity=(0.0, -g))
    floor = w.add_segment((-5.0, 0.0), (5.0, 0.0))
    box = w.add_polygon([(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)], kind="static",
                        position=(0.0, 2.0), restitution=0.0)
    w.step_to(0.5)
    w.set_kind(box, "dynamic")
    info = w.bodies[box]
    assert info.kind == "dynamic" and info.mass == pytest.approx(1.0)
    assert info.inertia == pytest.approx(1.0 / 6.0)
    assert w.pose(box) == pytest.approx((0.5, 2.5, 0.0))             # the centre of mass now
    events = [e for e in w.step_to(2.0) if e.kind == "collision"]
    assert events[0].b == floor or events[0].a == floor
    assert events[0].time == pytest.approx(0.5 + math.sqrt(2 * 2.0 / g), rel=1e-12)
    w.set_kind(box, "static")
    assert w.velocity(box) == (0.0, 0.0, 0.0) and w.bodies[box].kind == "static"
    y = w.pose(box)[1]
    w.step_to(3.0)
    assert w.pose(box)[1] == y


def test_set_mass_changes_the_response(engine) -> None:
    w = engine.World()
    a = w.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0))
    b = w.add_circle((3.0, 0.0), 0.5)
    w.set_mass(a, 3.0)
    w.set_mass(b, 1.0)
    w.step_to(5.0)
    # elastic head-on: va' = (ma - mb) / (ma + mb), vb' = 2 ma / (ma + mb)
    assert w.velocity(a)[0] == pytest.approx(0.5, rel=1e-14)
    assert w.velocity(b)[0] == pytest.approx(1.5, rel=1e-14)


def test_apply_impulse_at_a_point(engine) -> None:
    w = engine.World()
    box = w.add_polygon(SQUARE, mass=2.0, position=(1.0, 1.0))
    I = w.bodies[box].inertia
    w.apply_impulse(box, (0.0, 4.0), (1.5, 1.0))        # at its right edge, upwards
    vx, vy, omega = w.velocity(box)
    assert (vx, vy) == (0.0, 2.0) and omega == pytest.approx(0.5 * 4.0 / I, rel=1e-15)
    w.apply_impulse(box, (-2.0, 0.0))                   # at the centre of mass: no spin
    assert w.velocity(box) == pytest.approx((-1.0, 2.0, omega), rel=1e-15)
    wall = w.add_segment((5.0, 0.0), (5.0, 1.0))
    with pytest.raises(engine.EngineError, match="not a dynamic body"):
        w.apply_impulse(wall, (1.0, 0.0))


def test_static_bodies_refuse_velocity(engine) -> None:
    w = engine.World()
    wall = w.add_segment((5.0, 0.0), (5.0, 1.0))
    with pytest.raises(engine.EngineError, match="static body does not move"):
        w.set_velocity(wall, (1.0, 0.0))


def test_timer_cancel(engine) -> None:
    w = engine.World()
    fired = []
    t1 = w.add_timer(1.0, lambda world, ev: fired.append(1))
    w.add_timer(2.0, lambda world, ev: fired.append(2))
    t3 = w.add_timer(3.0, lambda world, ev: world.cancel_timer(t4))
    t4 = w.add_timer(4.0, lambda world, ev: fired.append(4))
    w.cancel_timer(t1)
    events = w.step_to(5.0)
    assert [e.time for e in events] == [2.0, 3.0] and fired == [2]
    with pytest.raises(engine.EngineError, match="no such timer"):
        w.cancel_timer(t3)


@pytest.mark.parametrize("cat_a,mask_a,cat_b,mask_b,meet", [
    (1, 0xFFFFFFFF, 1, 0xFFFFFFFF, True),
    (1, 0xFFFFFFFE, 1, 0xFFFFFFFF, False),   # a ignores category 1
    (2, 0xFFFFFFFF, 1, 0x1, False),          # b only meets category 1
    (2, 0x1, 1, 0x2, True),
])
def test_category_and_mask(engine, cat_a, mask_a, cat_b, mask_b, meet) -> None:
    w = engine.World()
    a = w.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0), category=cat_a, mask=mask_a)
    w.add_circle((3.0, 0.0), 0.5, category=cat_b, mask=mask_b)
    events = w.step_to(3.0)
    assert (len(events) == 1) == meet
    if meet:
        assert events[0].time == pytest.approx(2.0, rel=1e-15) and events[0].a == a


def test_polygons_in_either_winding(engine) -> None:
    w = engine.World()
    ccw = w.add_polygon([(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)], position=(0.0, 0.0))
    cw = w.add_polygon([(0.0, 0.0), (0.0, 1.0), (1.0, 0.0)], position=(5.0, 0.0))
    a, b = w.bodies[ccw], w.bodies[cw]
    assert a.mass == b.mass == pytest.approx(0.5) and a.inertia == pytest.approx(b.inertia)
    assert set(a.vertices) == set(b.vertices)
    with pytest.raises(engine.EngineError, match="convex"):
        w.add_polygon([(0.0, 0.0), (2.0, 0.0), (1.0, 0.2), (1.0, 1.0)], kind="static")


def _def(engine, ffi, lib, verts, **fields):
    d = ffi.new("m2c_body_def *", lib.m2c_default_body_def())
    flat = ffi.new("double[]", [c for v in verts for c in v])
    d.nvertices, d.vertices = len(verts), flat
    for k, v in fields.items():
        setattr(d, k, v)
    return d, flat


def test_c_default_def_and_zeroed_def(engine) -> None:
    """A zeroed def is refused by name; a default one is a dynamic body that collides; the
    core accepts a clockwise polygon and stores it anticlockwise."""
    from max2code.engine.binding import load
    ffi, lib = load()
    w = ffi.gc(lib.m2c_world_new(ffi.NULL), lib.m2c_world_free)
    zero = ffi.new("m2c_body_def *")
    flat = ffi.new("double[]", [0.0, 0.0])
    zero.nvertices, zero.vertices, zero.radius, zero.kind = 1, flat, 1.0, 2
    assert lib.m2c_world_add_body(w, zero) == -1
    assert "m2c_default_body_def" in ffi.string(lib.m2c_world_error(w)).decode()
    d = lib.m2c_default_body_def()
    assert (d.kind, d.group, d.category, d.mask, d.mass, d.restitution) == (2, -1, 1, 0xFFFFFFFF, 1.0, 1.0)
    a, fa = _def(engine, ffi, lib, [(0.0, 0.0)], radius=0.5, vx=1.0)
    b, fb = _def(engine, ffi, lib, [(0.0, 0.0)], radius=0.5, x=3.0)
    assert lib.m2c_world_add_body(w, a) == 0 and lib.m2c_world_add_body(w, b) == 1
    buf, count = ffi.new("m2c_event[]", 8), ffi.new("int *")
    assert lib.m2c_world_step(w, 3.0, buf, 8, count) == 0
    assert count[0] == 1 and buf[0].time == 2.0
    cw, fc = _def(engine, ffi, lib, [(0.0, 0.0), (0.0, 1.0), (1.0, 0.0)], kind=0, x=10.0)
    k = lib.m2c_world_add_body(w, cw)
    out = ffi.new("double[]", 6)
    assert lib.m2c_world_vertices(w, k, out, 3) == 3
    got = [(out[2 * i], out[2 * i + 1]) for i in range(3)]
    area = sum(got[i][0] * got[(i + 1) % 3][1] - got[(i + 1) % 3][0] * got[i][1] for i in range(3))
    assert area > 0 and set(got) == {(0.0, 0.0), (0.0, 1.0), (1.0, 0.0)}


def test_library_exports_only_the_public_api(engine) -> None:
    from max2code.engine.binding import declarations
    from max2code.engine.build import library
    if shutil.which("nm") is None:
        pytest.skip("nm is not installed")
    out = subprocess.run(["nm", "-D", "--defined-only", str(library())], capture_output=True,
                         text=True, check=True).stdout
    exported = {line.split()[-1] for line in out.splitlines() if line.split()[1:2] == ["T"]}
    public = set(re.findall(r"\b(m2c_\w+)\s*\(", declarations()))
    assert exported == public
