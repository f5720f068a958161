"""bench/engine.py's scenes and the exact answers it compares the engines with: checked here
against brute force and closed forms, so a wrong "exact" answer cannot make an engine look good
or bad."""

from __future__ import annotations

import math
import random
import sys
from pathlib import Path

import mpmath
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "bench"))

import engine_scenes as S  # noqa: E402


def test_disc_contact_time_is_the_first_touch() -> None:
    for scene, t in S.two_disc_trials(50):
        a, b = scene.bodies
        with mpmath.workdps(40):
            def dist(s):
                s = mpmath.mpf(s)
                return mpmath.hypot((b.x - a.x) + (b.vx - a.vx) * s, (b.y - a.y) + (b.vy - a.vy) * s)
            root = mpmath.findroot(lambda s: dist(s) - (a.r + b.r), t)
            assert abs(root - t) <= 1e-13 * t
            # never closer than the radius sum before: sampled every 1 ms
            assert min(dist(k * t / 1000) for k in range(1000)) > a.r + b.r
        assert 0.5 <= t <= 1.5


def test_disc_contact_time_misses_and_separating() -> None:
    a = S.Disc(1, m=1, x=0, y=0)
    assert S.disc_contact_time(a, S.Disc(1, m=1, x=5, y=0, vx=1)) is None          # moving away
    assert S.disc_contact_time(a, S.Disc(1, m=1, x=5, y=3, vx=-1)) is None         # passes above
    assert S.disc_contact_time(a, S.Disc(1, m=1, x=5, y=0, vx=-1)) == pytest.approx(3.0, rel=1e-15)
    assert S.disc_contact_time(a, S.Disc(1, m=1, x=5, y=0)) is None          # at rest


def test_square_wall_contact_without_spin_is_the_closed_form() -> None:
    body = S.Block(S.square(0.25), m=1.0, x=0.0, y=0.0, vx=2.0, angle=0.3)
    far = max(math.cos(0.3) * x - math.sin(0.3) * y for x, y in S.square(0.25))
    assert S.square_wall_contact(body, 1.5) == pytest.approx((1.5 - far) / 2.0, rel=1e-14)


def test_square_wall_contact_against_dense_sampling() -> None:
    for scene, t in S.square_wall_trials(30):
        body, wall_x = scene.bodies[0], scene.notes["wall_x"]

        def reach(s: float) -> float:
            a = body.angle + body.w * s
            return body.x + body.vx * s + max(math.cos(a) * x - math.sin(a) * y for x, y in body.vertices)

        assert reach(t) == pytest.approx(wall_x, abs=1e-12)
        step = 5e-5
        samples = [reach(k * step) for k in range(int(t / step))]
        assert max(samples) < wall_x                       # no earlier touch at any sample
        assert reach(t + 1e-6) > wall_x                    # it crosses, not grazes


def test_square_wall_graze_is_not_a_contact() -> None:
    # a spinning square at rest whose corner sweeps exactly up to the wall: touches, never crosses
    half = 0.25
    body = S.Block(S.square(half), m=1.0, x=0.0, y=0.0, w=3.0)
    assert S.square_wall_contact(body, half * math.sqrt(2) + 1e-9) is None
    assert S.square_wall_contact(body, half * math.sqrt(2) - 1e-3) is not None


def test_polygon_moment_and_area() -> None:
    assert S.polygon_moment(S.square(0.5), 3.0) == pytest.approx(3.0 * (1 + 1) / 12, rel=1e-15)
    rect = ((-1.0, -0.25), (1.0, -0.25), (1.0, 0.25), (-1.0, 0.25))
    assert S.polygon_area(rect) == 1.0
    assert S.polygon_moment(rect, 2.0) == pytest.approx(2.0 * (4 + 0.25) / 12, rel=1e-15)
    # equilateral triangle about its centroid: m a^2 / 12
    a = 0.7
    tri = tuple((a / math.sqrt(3) * math.cos(k * 2 * math.pi / 3 + 0.4), a / math.sqrt(3) * math.sin(k * 2 * math.pi / 3 + 0.4))
                for k in range(3))
    assert S.polygon_moment(tri, 5.0) == pytest.approx(5.0 * a * a / 12, rel=1e-12)


def test_energy_counts_kinetic_rotational_and_potential() -> None:
    scene = S.Scene("e", (S.Disc(0.5, m=2.0, x=1.0, y=3.0), S.Block(S.square(0.5), m=3.0, x=0.0, y=1.0)), gravity=(0.0, -10.0))
    states = [(1.0, 3.0, 0.0, 3.0, 4.0, 2.0), (0.0, 1.0, 0.0, 0.0, 1.0, 1.0)]
    kinetic = 0.5 * 2 * 25 + 0.5 * (0.5 * 2 * 0.25) * 4 + 0.5 * 3 * 1 + 0.5 * (3 * 2 / 12) * 1
    assert S.energy(scene, states) == pytest.approx(kinetic + 2 * 10 * 3 + 3 * 10 * 1, rel=1e-15)


def test_tunnel_trials_start_before_the_wall_and_end_past_it() -> None:
    for speed in S.TUNNEL_SPEEDS:
        trials = S.tunnel_trials(speed)
        assert len(trials) == 200
        for scene, t_end in trials:
            ball, = scene.bodies
            assert ball.r == 0.01 and ball.vx == speed and ball.vy == 0
            assert ball.x + ball.r < 0 and -1 < ball.y < 1          # aimed at the wall
            assert ball.x + speed * t_end == pytest.approx(1.0 - ball.r)
    assert S.tunnelled(0.3) and not S.tunnelled(-0.5)


@pytest.mark.parametrize("kind", ["sparse", "dense"])
@pytest.mark.parametrize("n", [10, 100, 1000])
def test_gas_is_as_specified(kind: str, n: int) -> None:
    scene = S.gas(n, kind)
    side = scene.notes["side"]
    area = sum(math.pi * b.r ** 2 for b in scene.bodies)
    assert area / side ** 2 == pytest.approx(S.GAS[kind]["fraction"], rel=1e-12)
    assert all(math.hypot(b.vx, b.vy) == pytest.approx(S.GAS[kind]["speed"]) for b in scene.bodies)
    assert all(b.r <= b.x <= side - b.r and b.r <= b.y <= side - b.r for b in scene.bodies)
    pts = sorted((b.x, b.y) for b in scene.bodies)
    r = S.GAS_RADIUS
    for i, (x, y) in enumerate(pts):                      # no overlap (sweep over x)
        for x2, y2 in pts[i + 1:]:
            if x2 - x >= 2 * r:
                break
            assert math.hypot(x2 - x, y2 - y) >= 2 * r


def test_idle_scene_never_collides_within_a_minute() -> None:
    scene = S.idle(100)
    side = scene.walls[1].a[0]
    for b in scene.bodies:
        for t in (0.0, 60.0):
            x, y = b.x + b.vx * t, b.y + b.vy * t
            assert b.r < x < side - b.r and b.r < y < side - b.r
    # closest approach of any two: pitch 8, each moves at most 0.6 m in 60 s
    assert min(math.hypot(a.x - b.x, a.y - b.y) for a in scene.bodies for b in scene.bodies if a is not b) >= 8.0


def test_energy_box_discs_start_apart_inside() -> None:
    scene = S.energy_box()
    assert len(scene.bodies) == 20 and scene.gravity == (0.0, -S.G)
    for i, a in enumerate(scene.bodies):
        assert a.r < a.x < 10 - a.r and a.r < a.y < 10 - a.r
        for b in scene.bodies[i + 1:]:
            assert math.hypot(a.x - b.x, a.y - b.y) > a.r + b.r
