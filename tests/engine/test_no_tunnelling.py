"""No tunnelling under default settings (issue 33, item 1): bodies never pass a floor.

A body whose height above a cell boundary rounded to one ulp got no downward crossing (the
cell-crossing prediction asked the root finder with an infinite window, where its window rule
missed the root), was never predicted against the floor again and fell through it. Each test
here failed before: the ball at y = -115.6 by t = 6, 15 of 800 balls below the floor, a box
lost in one of twelve spinning worlds (seed 11).
"""

from __future__ import annotations

import math
import random

import pytest

from .scenes import scatter

TOL = 1e-6


@pytest.mark.parametrize("cell_size", [0.0, -1.0])
@pytest.mark.parametrize("speed", [10.0, 13.0])
def test_elastic_ball_thrown_up_keeps_bouncing(engine, cell_size, speed):
    """An e = 1 ball of radius 1 thrown up from a floor: its apex height is 1 + v^2 / 2g for
    ever (the energy is kept), and it is never below the floor."""
    w = engine.World(gravity=(0, -9.81), cell_size=cell_size)
    w.add_segment((-5, 0), (5, 0))
    ball = w.add_circle((0, 1), 1.0, velocity=(0, speed))
    e0 = w.energy()
    for t in (1, 2, 3, 4.5, 6, 10, 20):
        w.step_to(t, events=False)
        assert w.pose(ball)[1] >= 1 - TOL, f"below the floor at t = {t}"
        assert w.energy() == pytest.approx(e0, rel=1e-9)
    # it still bounces: the number of floor contacts is the flight count
    flights = sum(e.kind == "collision" for e in w.step_to(40))
    assert flights == pytest.approx(20 / (2 * speed / 9.81), abs=1.5)


def balls_on_floor(World, seed: int):
    rng = random.Random(seed)
    w = World(gravity=(0, -9.81))
    w.add_segment((-10, 0), (10, 0))
    w.add_segment((-10, 0), (-10, 30))
    w.add_segment((10, 0), (10, 30))
    radius = 0.2
    balls = []
    for x, y in scatter(rng, 40, radius, 20, 10):
        balls.append(w.add_circle((x - 10, y + 0.3), rng.uniform(0.05, radius),
                                  velocity=(rng.uniform(-3, 3), rng.uniform(-3, 6)),
                                  restitution=rng.uniform(0.3, 1.0)))
    return w, balls


def test_random_worlds_of_balls_stay_above_the_floor(engine):
    """Within TOL of the floor and walls -- or within the contact solver's slop
    (docs/engine-contact.md) for a ball the solver holds or put to sleep."""
    below = []
    for seed in range(20):
        w, balls = balls_on_floor(engine.World, seed)
        w.step_to(5, events=False)
        for b in balls:
            x, y, _ = w.pose(b)
            r = w.bodies[b].radius
            tol = TOL + (w.contact_slop if w.solving(b) or w.asleep(b) else 0.0)
            if y < r - tol or abs(x) > 10 - r + tol:
                below.append((seed, b, x, y, r))
    assert below == []


def spinning_boxes(World, seed: int):
    """40 spinning square boxes falling in a 24 x 24 room."""
    rng = random.Random(seed)
    w = World(gravity=(0, -9.81))
    size = 24
    for a, b in [((0, 0), (size, 0)), ((size, 0), (size, size)), ((size, size), (0, size)),
                 ((0, size), (0, 0))]:
        w.add_segment(a, b)
    h = 0.3
    boxes = []
    for row in range(8):
        for col in range(5):
            x = 2.4 + col * 4.8 + rng.uniform(-0.5, 0.5)
            y = 1.5 + row * 2.8
            boxes.append(w.add_polygon([(-h, -h), (h, -h), (h, h), (-h, h)], position=(x, y),
                                       angle=rng.uniform(0, 2 * math.pi), omega=rng.uniform(-8, 8),
                                       velocity=(rng.uniform(-3, 3), rng.uniform(-3, 3))))
    return w, boxes, h, size


@pytest.mark.parametrize("seed", [11])
def test_spinning_boxes_stay_in_the_room(engine, seed):
    w, boxes, h, size = spinning_boxes(engine.World, seed)
    w.step_to(10, events=False)
    lost = [b for b in boxes if not all(h - TOL < c < size - h + TOL for c in w.pose(b)[:2])]
    assert lost == []


@pytest.mark.parametrize("speed", [3.0, 10.5])
def test_ball_sliding_off_a_floor_falls(engine, speed):
    """A ball sliding on a floor (the rest rule) leaves it at its end and falls: at the end it
    landed on the corner again at the same instant and slid on, in the air or (with the crossing
    rule above) for ever at one instant."""
    w = engine.World(gravity=(0, -9.81))
    w.add_segment((-5, 0), (5, 0))
    ball = w.add_circle((0, 0.3), 0.1, velocity=(speed, 0), restitution=0.5)
    w.step_to(5 / speed + 1.0)
    x, y, _ = w.pose(ball)
    assert x > 5 and y < -1
