"""Bodies the contact solver holds (docs/server.md, "Bodies the contact solver holds"): clients
get their chord, re-sent only when the truth would leave it by more than the hop plus the
solver's slop; every other body stays exact.

The bound is checked against World's own poses at every wake of the room (each solver tick is
one) and at random instants between, with the bound computed here from its documented terms
(h, |g|, the slop) and each body's reach from its shape, not from the room's tables."""

from __future__ import annotations

import json
import math
import random

from hypothesis import given, settings, strategies as st

from max2code.engine.limits import CONTACT_STEP
from max2code.engine.scenefile import Scene
from max2code.engine.world import World
from max2code.server.room import Room

from .client import Client

G = 9.81
H = CONTACT_STEP
VIEW = (-2.0, -0.5, 2.0, 4.5)


def _box(w: World, half_w: float, half_h: float, **kw) -> int:
    return w.add_polygon([(-half_w, -half_h), (half_w, -half_h), (half_w, half_h), (-half_w, half_h)], **kw)


def drop(seed: int, n: int, mu: float, e: float) -> tuple[World, dict[int, float]]:
    """Discs and boxes dropped into a bin (the engine tests' random small piles), and each
    dynamic body's reach (the farthest point of its shape from its reference point)."""
    rng = random.Random(seed)
    w = World(gravity=(0.0, -G))
    for a, b in (((-1.5, 0), (1.5, 0)), ((-1.5, 0), (-1.5, 4)), ((1.5, 0), (1.5, 4))):
        w.add_segment(a, b, friction=mu, restitution=e)
    centres: list[tuple[float, float]] = []
    while len(centres) < n:
        x, y = rng.uniform(-0.5, 0.5), rng.uniform(0.3, 2.5)   # (they land on each other)
        if all(math.hypot(x - a, y - b) > 0.45 for a, b in centres):
            centres.append((x, y))
    reach = {}
    for k, (x, y) in enumerate(centres):
        if k % 2:
            i = _box(w, 0.15, 0.1, position=(x, y), angle=rng.uniform(0, 3), restitution=e, friction=mu)
            reach[i] = math.hypot(0.15, 0.1)
        else:
            r = rng.uniform(0.1, 0.2)
            i = w.add_circle((x, y), r, restitution=e, friction=mu)
            reach[i] = r
    return w, reach


def serve(w: World, rate: float = 0.0) -> tuple[Room, Client, list[str], list[float]]:
    clock = [0.0]
    room = Room("held", Scene(name="held", bodies=(), view=VIEW), (), clock=lambda: clock[0],
                tolerance=0.0, world=w, rate=rate)
    inbox: list[str] = []
    _, text = room.join(inbox.append, "a", events=False)
    return room, Client.fed(text), inbox, clock


def off(c: Client, w: World, i: int, t: float) -> tuple[float, float, float]:
    """How far the client's pose of body i is from the world's at t: x, y, and the angle
    (a whole turn apart draws the same)."""
    (x, y, a), (X, Y, A) = c.pose(i, t), w.pose(i, t)
    turn = a - A
    turn -= 2 * math.pi * round(turn / (2 * math.pi))
    return abs(x - X), abs(y - Y), abs(turn)


def within_bound(w: World, reach: dict[int, float], until: float, instants: int) -> tuple[int, int, int]:
    """With every change sent at once (rate 0): at every wake (every tick, every event) and at
    two random instants before the next, a body the solver holds is drawn within
    slop + |g| h^2 / 8 of World's pose along x and y and through rotation at its reach; any
    other body exactly (1e-9 of the view); the same for a client joining at a random wake
    (its world message re-expresses what the others hold at its time). How many held poses
    were checked, and of those how many on a quadratic (a segment with an angular
    acceleration: reckon.fitted's) and how many on a cubic (with jerks: protocol 6)."""
    samples = random.Random(instants)
    room, c, inbox, clock = serve(w)
    clients = [(c, inbox)]
    late = samples.random() * until / 2
    bound = w.contact_slop + G * H * H / 8
    exact = 1e-9 * (VIEW[3] - VIEW[1])
    held_checks = quadratic = cubic = 0
    while (t := room.next_wake()) <= until:
        clock[0] = t
        room.advance(t)
        if t >= late and len(clients) == 1:
            box: list[str] = []
            clients.append((Client.fed(room.join(box.append, "late", events=False)[1]), box))
        for c, inbox in clients:
            for m in map(json.loads, inbox):
                c.apply(m)
            inbox.clear()
        after = min(room.next_wake(), until)
        for s in (t, t + samples.random() * (after - t), t + samples.random() * (after - t)):
            for i in reach:
                for c, _ in clients:
                    dx, dy, turn = off(c, w, i, s)
                    limit = bound * (1 + 1e-9) if w.solving(i) else exact
                    held_checks += w.solving(i)
                    quadratic += w.solving(i) and len(c.segs[i][0]) == 10
                    cubic += w.solving(i) and len(c.segs[i][0]) > 10
                    assert dx <= limit and dy <= limit and turn * reach[i] <= limit + 1e-15, \
                        (i, s, w.solving(i), len(c.segs[i][0]), dx, dy, turn * reach[i], limit)
    return held_checks, quadratic, cubic


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 10_000), n=st.integers(2, 5), mu=st.sampled_from([0.0, 0.5]),
       e=st.sampled_from([0.0, 0.3]), instants=st.integers(0, 2**32))
def test_clients_stay_within_the_hop_and_slop_of_the_truth(seed, n, mu, e, instants):
    """Random drops of discs and boxes: held bodies within the bound, the others exact."""
    w, reach = drop(seed, n, mu, e)
    held_checks, _, _ = within_bound(w, reach, 2.0, instants)
    assert held_checks > 0       # (the solver held something: the bound was exercised)


def tipping(shape: str, angle: float, size: float, mu: float) -> tuple[World, dict[int, float]]:
    """A box (half sides `size` by 0.8 `size`) or a dumbbell (two discs of radius 0.3 `size`
    on a bar, 2 `size` apart; symmetric, so its centre of mass is its middle) turned `angle`,
    its lowest point 1 cm above the floor: it pivots on that point with a growing spin and
    falls flat (the tipping-box and compound scenes). Its reach from its geometry."""
    w = World(gravity=(0.0, -G))
    w.add_segment((-50, 0), (50, 0), friction=mu)
    if shape == "box":
        hw, hh = size, 0.8 * size
        low = hw * math.sin(angle) + hh * math.cos(angle)
        i = _box(w, hw, hh, position=(0, 0.01 + low), angle=angle, restitution=0, friction=mu)
        return w, {i: math.hypot(hw, hh)}
    r = 0.3 * size
    low = size * math.sin(angle) + r
    parts = [(((-size, 0.0),), r), (((size, 0.0),), r), (((-size, 0.0), (size, 0.0)), 0.04 * size)]
    i = w.add_compound(parts, position=(0, 0.01 + low), angle=angle, restitution=0, friction=mu)
    return w, {i: size + r}


@settings(max_examples=12, deadline=None)
@given(shape=st.sampled_from(["box", "dumbbell"]), angle=st.floats(0.3, 0.9),
       size=st.floats(0.15, 0.4), mu=st.sampled_from([0.3, 0.6]), instants=st.integers(0, 2**32))
def test_tipping_bodies_get_quadratics_within_the_bound(shape, angle, size, mu, instants):
    """A box and a dumbbell tipping over: the solver holds them while their spin grows, their
    smooth history gets them quadratics (angle + omega s + alpha s^2/2: protocol version 5)
    or cubics (+ j s^3/6: version 6), and those are drawn within the bound at every tick and
    at random instants. (A sign error in alpha or a jerk anywhere, on the server or in the
    client's evaluation, puts the drawn pose some alpha s^2 reach, 1e-3 m over a few ticks,
    or j s^3 reach / 3, some 1e-4 m over ten, from the truth: far past 3.1e-5 m.)"""
    w, reach = tipping(shape, angle, size, mu)
    held_checks, quadratic, cubic = within_bound(w, reach, 1.5, instants)
    assert quadratic + cubic > 0, held_checks


def test_tipping_boxes_get_cubics():
    """Of the tipping runs above, the box of the tipping-box scene (0.6 rad, half sides 0.25)
    and a dumbbell: some of their held poses are drawn from cubics (the bound held on them,
    above)."""
    for shape, size in (("box", 0.25), ("dumbbell", 0.3)):
        w, reach = tipping(shape, 0.6, size, 0.5)
        held_checks, _, cubic = within_bound(w, reach, 1.5, 7)
        assert cubic > 0, (shape, held_checks)


def column(conveyor: float) -> tuple[World, list[int]]:
    """Three 0.5 m boxes stacked 1e-6 m apart on a floor (a kinematic one moving at `conveyor`
    m/s): they land at the first tick and settle on it."""
    w = World(gravity=(0.0, -G))
    w.add_segment((-50, 0), (50, 0), kind="kinematic" if conveyor else "static",
                  velocity=(conveyor, 0.0), friction=0.5)
    return w, [_box(w, 0.25, 0.25, position=(0, 0.25 + k * (0.5 + 1e-6) + 1e-6), restitution=0,
                    friction=0.5) for k in range(3)]


def held_segments(w: World, until: float) -> tuple[list[tuple[float, int]], Room]:
    """(time, body) of every segment the page's stream (60 messages a second at most) carries
    for a body the solver holds, over `until` seconds."""
    room, c, inbox, clock = serve(w, rate=60.0)
    out = []
    while (t := room.next_wake()) <= until:
        clock[0] = t
        room.advance(t)
        for m in map(json.loads, inbox):
            out += [(m["t"], seg[0]) for seg in m.get("seg", []) + m.get("fall", []) if w.solving(seg[0])]
        inbox.clear()
    return out, room


def test_a_column_riding_a_conveyor_sends_nothing_once_at_rest():
    """On a floor moving at 0.3 m/s the column never sleeps (it moves) but rests on the belt:
    from 1 s to 4 s the solver holds all three, and their exact segments change every tick
    (the hop). Before: a segment for each in every message, 60 a second (540 in all); now
    none: their chords (0.3 m/s along, standing up) stay within the bound."""
    w, boxes = column(0.3)
    sent, _ = held_segments(w, 4.0)
    assert all(w.solving(b) and not w.asleep(b) for b in boxes)
    assert [s for s in sent if s[0] >= 1.0] == []
    for b in boxes:     # (and they do ride the belt: 0.3 m/s)
        assert abs(w.velocity(b, 4.0)[0] - 0.3) < 1e-6


def test_a_resting_column_sends_nothing_until_it_sleeps():
    """On a static floor the same column rests until it sleeps (at 0.25 s: the calm time):
    before, a segment for each box in every message until then; now one each at the landing
    and one each when they fall asleep (rest is exact again), none between."""
    w, boxes = column(0.0)
    sent, room = held_segments(w, 1.0)
    assert all(w.asleep(b) for b in boxes)
    assert [s for s in sent if s[0] > 0.05] == []
    assert len(sent) <= 3


def test_a_ball_rolling_on_a_floor_is_sent_once():
    """A ball rolling without slipping at 0.5 m/s is held by the solver for ever (no rolling
    resistance, too fast to sleep): its exact segment changes every tick (the hop), its chord
    never. Before: 60 messages a second; now: its landing and its push out of the slop."""
    w = World(gravity=(0.0, -G))
    w.add_segment((-50, 0), (50, 0), friction=0.5)
    ball = w.add_circle((0, 0.1 + 1e-6), 0.1, velocity=(0.5, 0), omega=-5.0, restitution=0,
                        friction=0.5)
    room, c, inbox, clock = serve(w, rate=60.0)
    count = 0
    while (t := room.next_wake()) <= 3.0:
        clock[0] = t
        room.advance(t)
        count += len(inbox)
        for m in map(json.loads, inbox):
            c.apply(m)
        inbox.clear()
    assert w.solving(ball)
    assert count <= 3, count
    x, y, _ = c.pose(ball, 3.0)
    assert abs(x - 1.5) <= 1e-4 and abs(y - 0.1) <= 1e-4   # rolled v t (the engine tests' closed form)


def test_a_world_that_starts_in_contact_is_stepped():
    """A ball put down on the floor has its first event at 0, the room's own time: the room
    stepped nothing at its time (advance returned) and its loop woke at 0 for ever."""
    w = World(gravity=(0.0, -G))
    w.add_segment((-50, 0), (50, 0), friction=0.5)
    ball = w.add_circle((0, 0.1), 0.1, velocity=(0.5, 0), omega=-5.0, restitution=0, friction=0.5)
    room, c, inbox, clock = serve(w, rate=60.0)
    wakes = 0
    while (t := room.next_wake()) <= 1.0 and wakes < 10_000:
        wakes += 1
        clock[0] = t
        room.advance(t)
    assert w.time > 0.99 and w.solving(ball), (wakes, w.time)
