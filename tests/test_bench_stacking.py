"""bench/engine_stacking.py's scenes and measures (issue 34, item 5): the overlap, tilt and mixing
it reports for every engine are checked here against closed forms and exact rational geometry, so
that a wrong measure cannot make an engine look good or bad."""

from __future__ import annotations

import math
import random
import sys
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "bench"))

import engine_scenes as S  # noqa: E402
import engine_stacking as K  # noqa: E402


def square_at(x: float, y: float, half: float = 0.5, angle: float = 0.0):
    c, s = math.cos(angle), math.sin(angle)
    return tuple((x + vx * c - vy * s, y + vx * s + vy * c) for vx, vy in S.square(half))


def test_axis_aligned_squares_overlap_by_their_shared_width() -> None:
    # unit squares whose centres are 0.9 apart along x and 0.2 along y: 0.1 deep along x
    assert K.polygon_depth(square_at(0, 0), square_at(0.9, 0.2)) == pytest.approx(0.1, abs=1e-12)
    assert K.polygon_depth(square_at(0, 0), square_at(1.0, 0.0)) == 0.0      # touching
    assert K.polygon_depth(square_at(0, 0), square_at(1.3, 1.3)) == 0.0


def test_a_corner_below_a_floor_is_as_deep_as_it_is_below() -> None:
    # a square turned 45 degrees, its lowest corner d below the floor segment
    d = 0.03
    half_diag = 0.5 * math.sqrt(2)
    sq = square_at(0.0, half_diag - d, angle=math.pi / 4)
    assert K.polygon_depth(sq, ((-5.0, 0.0), (5.0, 0.0))) == pytest.approx(d, abs=1e-12)
    sq = square_at(0.0, half_diag + d, angle=math.pi / 4)
    assert K.polygon_depth(sq, ((-5.0, 0.0), (5.0, 0.0))) == 0.0


def test_discs_against_discs_and_polygons() -> None:
    assert K.depth(("disc", (0, 0), 1.0), ("disc", (1.5, 0), 1.0)) == pytest.approx(0.5)
    sq = ("poly", square_at(0, 0))
    assert K.depth(("disc", (0.8, 0.0), 0.5), sq) == pytest.approx(0.2)         # outside, 0.3 away
    assert K.depth(sq, ("disc", (0.4, 0.0), 0.2)) == pytest.approx(0.3)         # centre inside
    assert K.depth(("disc", (0.0, 2.0), 0.5), sq) == 0.0


def exact_depth(p, q) -> Fraction:
    """Penetration depth of two axis-aligned rectangles in rationals: the shortest of the four
    moves of q (left, right, down, up) after which the two share no interior point, found by
    trying each (0 when they share none already)."""
    def extent(poly, k):
        return min(Fraction(v[k]) for v in poly), max(Fraction(v[k]) for v in poly)
    (ax0, ax1), (ay0, ay1), (bx0, bx1), (by0, by1) = extent(p, 0), extent(p, 1), extent(q, 0), extent(q, 1)
    if min(ax1, bx1) <= max(ax0, bx0) or min(ay1, by1) <= max(ay0, by0):
        return Fraction(0)
    return min(ax1 - bx0, bx1 - ax0, ay1 - by0, by1 - ay0)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.floats(-2, 2, allow_nan=False), min_size=8, max_size=8))
def test_rectangle_depth_against_exact_rationals(v) -> None:
    x0, w0, y0, h0, x1, w1, y1, h1 = v
    def rect(x, w, y, h):
        w, h = abs(w) + 0.1, abs(h) + 0.1
        return ((x, y), (x + w, y), (x + w, y + h), (x, y + h))
    p, q = rect(x0, w0, y0, h0), rect(x1, w1, y1, h1)
    assert K.polygon_depth(p, q) == pytest.approx(float(exact_depth(p, q)), abs=1e-12)


@pytest.mark.parametrize("angle, want", [(0.0, 0.0), (0.1, 0.1), (-0.1, 0.1), (math.pi / 2 - 0.1, 0.1),
                                         (math.pi, 0.0), (math.pi / 4, math.pi / 4),
                                         (3 * math.pi / 4 + 0.05, math.pi / 4 - 0.05), (-7.0, 7 - 2 * math.pi)])
def test_tilt_is_the_angle_from_the_nearest_side(angle: float, want: float) -> None:
    assert K.tilt(angle) == pytest.approx(want, abs=1e-12)


@pytest.mark.parametrize("mixing, mix", [
    (("product", "product"), (lambda a, b: a * b, lambda a, b: a * b)),           # pymunk
    (("sqrt", "max"), (lambda a, b: math.sqrt(a * b), max)),                     # Box2D
    (("sqrt", "product"), (lambda a, b: math.sqrt(a * b), lambda a, b: a * b)),  # ours
])
def test_each_engine_mixes_back_the_scenes_coefficients(mixing, mix) -> None:
    scene = S.Scene("x", (), friction=0.36, restitution=0.8, rest=True)
    f, e = scene.coefficients(1.0, *mixing)
    assert mix[0](f, f) == pytest.approx(0.36)
    assert mix[1](e, e) == pytest.approx(0.8)
    # without a scene restitution, the bodies' own e is passed through
    assert S.Scene("y", ()).coefficients(0.7, *mixing) == (0.0, 0.7)


@pytest.mark.parametrize("angle", [0.2, 0.6, 1.2])
def test_the_tilted_box_starts_a_centimetre_above_the_floor(angle: float) -> None:
    b = K.tilted_drop(angle, 0.0, 0.5).bodies[0]
    corners = square_at(b.x, b.y, K.BOX, b.angle)
    assert min(y for _, y in corners) == pytest.approx(0.01, abs=1e-12)
    assert b.angle == angle


def test_scenes_start_without_overlap_and_jittered_boxes_nearly_touch() -> None:
    for scene, _ in K.scenes(quick=False):
        states = [(b.x, b.y, b.angle) for b in scene.bodies]
        assert K.deepest(scene, states) == 0.0, scene.name
    jittered = K.column(jitter=True)
    tops = [max(y for _, y in square_at(b.x, b.y, K.BOX, b.angle)) for b in jittered.bodies]
    bottoms = [min(y for _, y in square_at(b.x, b.y, K.BOX, b.angle)) for b in jittered.bodies]
    gaps = [bottoms[k + 1] - tops[k] for k in range(len(tops) - 1)]
    assert all(g == pytest.approx(0.001, abs=1e-12) for g in gaps)
    assert max(abs(b.angle) for b in jittered.bodies) <= 0.02
    assert 0 < max(abs(b.angle) for b in jittered.bodies)


def test_deepest_finds_the_one_overlapping_pair_among_many() -> None:
    rng = random.Random(3)
    discs = tuple(S.Disc(0.1, m=1.0, x=0.5 * i, y=0.5 + rng.uniform(-0.01, 0.01)) for i in range(40))
    scene = S.Scene("row", discs, K.FLOOR)
    states = [(d.x, d.y, 0.0) for d in discs]
    assert K.deepest(scene, states) == 0.0
    states[17] = (states[16][0] + 0.15, states[16][1], 0.0)      # 0.05 into its neighbour
    assert K.deepest(scene, states) == pytest.approx(0.05, abs=1e-12)
    states[30] = (states[30][0], 0.08, 0.0)                      # 0.02 into the floor
    assert K.deepest(scene, states) == pytest.approx(0.05, abs=1e-12)
    states[17] = (states[16][0] + 0.5, states[16][1], 0.0)
    assert K.deepest(scene, states) == pytest.approx(0.02, abs=1e-12)
