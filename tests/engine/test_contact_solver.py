"""The sustained-contact solver (issue 34, docs/engine-contact.md) against closed-form physics
and an independent statics check (force_oracle.py), never against the engine's own output.

Without the solver (contact_step = 0; the default is 1/240 s) the engine freezes each of these:
the tilted box balanced on its corner, the sliding box where it lands, the box on the slope
where it was put -- the rest rule decides there. With it the box tips flat, slides
v0^2 / (2 mu g) and stops, and accelerates at g (sin - mu cos) down the slope; a body sleeps
only when contact forces that hold it exist."""

from __future__ import annotations

import copy
import math
import pickle
import random
from fractions import Fraction

import pytest
from hypothesis import assume, given, settings, strategies as st

from max2code.engine.limits import CONTACT_STEP

from .force_oracle import Shape, balance, contacts, sleeping_residual, world_shapes
from .test_rest import _pile as _rest_pile
from .scenes import assert_apart, engine_floats

G = 9.81
H = 1 / 240          # the solver's step in these tests
CERTIFIED = 1e-6     # the oracle's residual (force / weight) below which forces hold a body


def _floor(w, mu: float, e: float, half: float = 50.0) -> int:
    return w.add_segment((-half, 0.0), (half, 0.0), friction=mu, restitution=e)


def _box(w, width: float, height: float, **kw) -> int:
    a, b = width / 2, height / 2
    return w.add_polygon([(-a, -b), (a, -b), (a, b), (-a, b)], **kw)


def _lowest(half: float, angle: float) -> float:
    """How far the lowest corner of a square (half side) turned by `angle` lies below its centre."""
    c, s = math.cos(angle), math.sin(angle)
    return max(-(x * s + y * c) for x in (-half, half) for y in (-half, half))


# -- the oracle itself, on cases whose answer is known -----------------------------------------

def _square(cx: float, cy: float, half: float, angle: float, mu: float) -> Shape:
    c, s = math.cos(angle), math.sin(angle)
    pts = tuple((cx + c * x - s * y, cy + s * x + c * y)
                for x, y in ((-half, -half), (half, -half), (half, half), (-half, half)))
    return Shape(pts, 0.0, (cx, cy), 1.0, mu, False)


FLOOR = Shape(((-5.0, 0.0), (5.0, 0.0)), 0.0, (0.0, 0.0), math.inf, 0.5, True)


def test_oracle_holds_a_flat_box_and_not_one_on_its_corner() -> None:
    """Flat: two corner forces of m g / 2 balance it. On a corner at 0.6 rad the weight's arm
    about the corner is 0.25 (cos 0.6 - sin 0.6) ~ 0.065 m: no force at the corner cancels that
    torque, whatever the friction."""
    flat = [FLOOR, _square(0.0, 0.25, 0.25, 0.0, 0.5)]
    assert balance(flat, contacts(flat, 1e-6), (0.0, -G)) < 1e-12
    tilted = [FLOOR, _square(0.0, _lowest(0.25, 0.6), 0.25, 0.6, 0.5)]
    assert len(contacts(tilted, 1e-6)) == 1
    assert balance(tilted, contacts(tilted, 1e-6), (0.0, -G)) > 0.1


def test_oracle_ball_on_ball_offset_sideways_is_not_held() -> None:
    """The issue's pile.toml at 3 s: a ball asleep on another, 0.0165 to the side. Frictionless,
    the one contact force points along the centres' line, not up: no balance."""
    low = Shape(((0.0, 0.1),), 0.1, (0.0, 0.1), 1.0, 0.0, True)
    dx = 0.0165
    top = Shape(((dx, 0.1 + math.sqrt(0.04 - dx * dx)),), 0.1,
                (dx, 0.1 + math.sqrt(0.04 - dx * dx)), 1.0, 0.0, False)
    found = contacts([low, top], 1e-9)
    assert len(found) == 1
    assert balance([low, top], found, (0.0, -G)) > 0.05


# -- a box dropped on its corner tips flat ------------------------------------------------------

@pytest.mark.parametrize("angle", [0.2, 0.6, 1.2])
@pytest.mark.parametrize("e", [0.0, 0.5])
@pytest.mark.parametrize("mu", [0.0, 0.5])
def test_tilted_box_ends_flat_and_certified(engine, angle: float, e: float, mu: float) -> None:
    """A 0.5 m box turned `angle`, its lowest corner 1 cm above the floor. Its centre of mass
    lies beyond the supporting corner (any angle not a multiple of pi/2), so it must turn to the
    nearer flat side: 0 for 0.2 and 0.6 rad, pi/2 for 1.2 rad (pymunk: 0.019 rad, Box2D 0.0013)."""
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    _floor(w, mu, e)
    b = _box(w, 0.5, 0.5, position=(0.0, _lowest(0.25, angle) + 0.01), angle=angle,
             restitution=e, friction=mu)
    w.step_to(5.0, events=False)
    x, y, th = w.pose(b)
    flat = round(angle / (math.pi / 2)) * math.pi / 2
    assert abs(th - flat) < 0.02
    assert y == pytest.approx(0.25, abs=1e-6)            # lying on a side, not a corner
    assert w.asleep(b)
    assert sleeping_residual(w) < CERTIFIED
    if mu == 0.0:
        assert abs(x) < 1e-9       # no horizontal force at all: the centre falls straight down
    assert_apart(w)


# -- sliding on a floor --------------------------------------------------------------------------

def _sliding(engine, mu: float, v0: float = 2.0, drop: float = 1e-6):
    """A 0.4 x 0.2 box landing flat (from `drop` above the floor) moving sideways at v0."""
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    _floor(w, mu, 0.0)
    b = _box(w, 0.4, 0.2, position=(0.0, 0.1 + drop), velocity=(v0, 0.0), restitution=0.0,
             friction=mu)
    return w, b, math.sqrt(2 * drop / G)


@pytest.mark.parametrize("mu", [0.3, 0.5])
def test_sliding_box_stops_after_the_coulomb_distance(engine, mu: float) -> None:
    """Kinetic friction mu m g decelerates it at mu g: it stops after v0 / (mu g) s, having slid
    v0^2 / (2 mu g) m (0.680 m for mu = 0.3), and then it stays."""
    v0 = 2.0
    w, b, landing = _sliding(engine, mu, v0)
    t_stop = v0 / (mu * G)
    stopped = None
    t = 0.0
    while t < t_stop + 0.5:
        t += H / 2
        w.step_to(t, events=False)
        if stopped is None and w.velocity(b)[0] <= 1e-12:
            stopped = t
    x, y, th = w.pose(b)
    assert x - v0 * landing == pytest.approx(v0 * v0 / (2 * mu * G), rel=0.02)
    assert stopped - landing == pytest.approx(t_stop, rel=0.02)
    assert abs(th) < 1e-9 and y == pytest.approx(0.1, abs=1e-6)
    w.step_to(t_stop + 2.0, events=False)
    assert w.pose(b)[0] == x and w.asleep(b)
    assert sleeping_residual(w) < CERTIFIED


def test_frictionless_box_keeps_its_speed(engine) -> None:
    """mu = 0: nothing acts along the floor, the box slides on at 2 m/s (the rest rule had
    stopped it dead where it landed)."""
    w, b, landing = _sliding(engine, 0.0)
    w.step_to(3.0, events=False)
    x, y, th = w.pose(b)
    assert w.velocity(b)[0] == pytest.approx(2.0, rel=1e-12)
    assert x == pytest.approx(2.0 * 3.0, rel=1e-9)
    assert y == pytest.approx(0.1, abs=1e-6) and abs(th) < 1e-9
    assert not w.asleep(b)


# -- rolling ---------------------------------------------------------------------------------------

ROLLING = 1e-9   # relative: speed, spin and distance of a rolling ball over 10 s (docs/engine-contact.md)
HOP = G * H / 2  # a resting body's vertical speed between ticks: it hops (docs/engine-contact.md),
HOP_HIGH = G * H * H / 8   # ... leaving at |g| h / 2 and landing at the next tick, this high


@pytest.mark.parametrize("mu", [0.3, 1.0])
def test_rolling_ball_keeps_rolling(engine, mu: float) -> None:
    """A disc rolling without slipping (omega = -v / r) on a floor with friction: the contact
    point is at rest, no friction acts, and nothing else slows it (no rolling resistance is
    modelled): after 10 s it still rolls at v0, spins at -v0 / r and has gone v0 t."""
    r, v0 = 0.2, 1.5
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    _floor(w, mu, 0.0, half=100.0)
    b = w.add_circle((0.0, r), r, velocity=(v0, 0.0), omega=-v0 / r, friction=mu, restitution=0.0)
    w.step_to(10.0, events=False)
    x, y, _ = w.pose(b)
    vx, vy, om = w.velocity(b)
    assert w.solving(b) and not w.asleep(b)
    assert vx == pytest.approx(v0, rel=ROLLING) and abs(vy) <= HOP * (1 + ROLLING)
    assert om == pytest.approx(-v0 / r, rel=ROLLING)
    assert x == pytest.approx(v0 * 10.0, rel=ROLLING) and y == pytest.approx(r, abs=1e-6 + HOP_HIGH)


def _spinning_drop(engine, r: float, v0: float, w0: float, mu: float, drop: float):
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    _floor(w, mu, 0.0, half=1000.0)
    b = w.add_circle((0.0, r + drop), r, velocity=(v0, 0.0), omega=w0, friction=mu,
                     restitution=0.0)
    return w, b


@settings(max_examples=25, deadline=None)
@given(r=engine_floats(0.05, 0.5), v0=engine_floats(-3.0, 3.0), w0=engine_floats(-30.0, 30.0),
       mu=engine_floats(0.1, 1.0), drop=st.one_of(st.just(0.0), engine_floats(0.0, 0.2)))
def test_spinning_ball_ends_rolling_as_the_closed_form_says(engine, r, v0, w0, mu, drop) -> None:
    """A uniform disc (I = m r^2 / 2) put down or dropped on a floor with friction, moving at v0
    and spinning at w0 (anticlockwise positive): friction and the floor's push act at the
    contact point, gravity through the centre, so the angular momentum about the contact point,
    -m r v + I w, is kept; friction ends the slip when w = -v / r, so it rolls on at
    v = (2 v0 - r w0) / 3 -- whatever mu and however it landed. (Rolling slower than the
    sleep speed, max(v_r, |g| h) = 0.041 m/s, it may fall asleep: not tried here.)"""
    vf = (2 * v0 - r * w0) / 3
    assume(abs(vf) > 0.1)
    w, b = _spinning_drop(engine, r, v0, w0, mu, drop)
    slip = abs(v0 + w0 * r)
    ends = math.sqrt(2 * drop / G) + slip / (3 * mu * G)   # the slip's end, at the latest
    w.step_to(ends + 0.5, events=False)
    vx, vy, om = w.velocity(b)
    assert vx == pytest.approx(vf, rel=ROLLING, abs=1e-12)
    assert om * r == pytest.approx(-vf, rel=ROLLING, abs=1e-12)
    assert abs(vy) <= HOP * (1 + ROLLING) and w.pose(b)[1] == pytest.approx(r, abs=1e-6 + HOP_HIGH)


@pytest.mark.parametrize("v0, w0, mu", [(2.0, 5.0, 0.5), (-1.0, 30.0, 0.2), (0.5, -20.0, 0.8)])
def test_spinning_ball_slips_for_the_coulomb_time(engine, v0: float, w0: float, mu: float) -> None:
    """Put down slipping at s0 = v0 + w0 r: kinetic friction mu m g slows the slip at
    mu g (1 + m r^2 / I) = 3 mu g, so it rolls from s0 / (3 mu g) on (within a step or two of
    the solver's)."""
    r = 0.2
    w, b = _spinning_drop(engine, r, v0, w0, mu, 0.0)
    ends = abs(v0 + w0 * r) / (3 * mu * G)

    def slip() -> float:
        vx, _, om = w.velocity(b)
        return abs(vx + om * r)

    w.step_to(ends - 2 * H, events=False)
    assert slip() > mu * G * H
    w.step_to(ends + 2 * H, events=False)
    assert slip() < 1e-12


# -- a slope -------------------------------------------------------------------------------------

def _on_slope(engine, k: float, theta: float = 0.3):
    """A 0.4 x 0.2 box at rest on a theta slope (descending towards +x), mu = k tan(theta)."""
    mu = k * math.tan(theta)
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    c, s = math.cos(theta), math.sin(theta)
    w.add_segment((-20 * c, 20 * s), (20 * c, -20 * s), friction=mu, restitution=0.0)
    start = (s * (0.1 + 1e-6), c * (0.1 + 1e-6))
    b = _box(w, 0.4, 0.2, position=start, angle=-theta, restitution=0.0, friction=mu)
    return w, b, start, mu


@pytest.mark.parametrize("k", [0.0, 0.8, 0.95])
def test_box_slides_down_a_slope_at_the_coulomb_acceleration(engine, k: float) -> None:
    """tan(theta) > mu: it slides, a = g (sin theta - mu cos theta): s = a t^2 / 2 along it."""
    theta = 0.3
    w, b, start, mu = _on_slope(engine, k, theta)
    a = G * (math.sin(theta) - mu * math.cos(theta))
    for t in (0.5, 1.0):
        w.step_to(t, events=False)
        x, y, th = w.pose(b)
        along = (x - start[0]) * math.cos(theta) - (y - start[1]) * math.sin(theta)
        assert along == pytest.approx(a * t * t / 2, rel=0.03)
        assert th == pytest.approx(-theta, abs=1e-9)      # it slides, it does not tip
    assert not w.asleep(b)


@pytest.mark.parametrize("k", [1.05, 1.2])
def test_box_sticks_on_a_slope_when_friction_holds(engine, k: float) -> None:
    """tan(theta) <= mu: static friction holds it where it was put, asleep with forces that
    the oracle finds inside the cone."""
    w, b, start, mu = _on_slope(engine, k)
    w.step_to(1.0, events=False)
    assert math.dist(w.pose(b)[:2], start) < 1e-5
    assert w.asleep(b)
    assert sleeping_residual(w) < CERTIFIED


# -- stacks --------------------------------------------------------------------------------------

@pytest.mark.parametrize("mu", [0.0, 0.5])
def test_column_of_ten_boxes_stands(engine, mu: float) -> None:
    """Ten 0.5 m boxes, 1e-6 m apart: they settle onto each other (1e-5 m in all), sleep
    certified, and then do not move at all for 10 s."""
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    _floor(w, mu, 0.0, half=5.0)
    boxes = [_box(w, 0.5, 0.5, position=(0.0, 0.25 + k * (0.5 + 1e-6) + 1e-6), restitution=0.0,
                  friction=mu) for k in range(10)]
    w.step_to(1.0, events=False)
    settled = [w.pose(b) for b in boxes]
    assert all(w.asleep(b) for b in boxes)
    for k, (x, y, th) in enumerate(settled):
        # the ten land at once at the first tick; its cold solve leaves a sway that dies out
        # and a lean within a few slops (measured with mu = 0.5: 6.2e-6 m at the top, 4e-7 rad)
        assert abs(x) < 1e-5 and abs(th) < 1e-6
        assert y == pytest.approx(0.25 + 0.5 * k, abs=2e-5)
    assert sleeping_residual(w) < CERTIFIED
    w.step_to(11.0, events=False)
    assert [w.pose(b) for b in boxes] == settled


@pytest.mark.parametrize("mu", [0.0, 0.5])
def test_column_put_down_touching_never_moves(engine, mu: float) -> None:
    """Issue 34 item 4: ten 0.5 m boxes put down at rest, each exactly on the one below (centres
    at 1/4 + k/2, exact in binary). Forces that hold them exist at t = 0 (the oracle finds them),
    so staying put is their motion: over 10 s no box moves 1e-9 m from its exact pose
    (rationals), and they sleep certified at once. (Before: the soft contacts at t = 0 gave each
    a hop and a sway, the solver ran 0.25 s before a certificate was tried, and they slept
    5.6e-6 m from where they were put.)"""
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    _floor(w, mu, 0.0, half=5.0)
    exact = [(Fraction(0), Fraction(1, 4) + Fraction(k, 2)) for k in range(10)]
    boxes = [_box(w, 0.5, 0.5, position=(float(x), float(y)), restitution=0.0, friction=mu)
             for x, y in exact]
    shapes = world_shapes(w, set(boxes))
    assert balance(shapes, contacts(shapes, 1e-9), (0.0, -G)) < CERTIFIED
    w.step_to(H / 2, events=False)          # before the solver's first tick
    assert all(w.asleep(b) for b in boxes)
    assert sleeping_residual(w) < CERTIFIED
    for t in range(1, 21):
        w.step_to(t / 2, events=False)
        for b, (x, y) in zip(boxes, exact):
            px, py, th = (Fraction(v) for v in w.pose(b))
            assert (px - x) ** 2 + (py - y) ** 2 < Fraction(1, 10 ** 18) and abs(th) < 1e-9


def _jittered_column(w, rng: random.Random, n: int = 10) -> list[int]:
    """bench/engine_stacking.py's jittered column: each 0.5 m box offset up to 3 mm sideways
    and turned up to 0.02 rad, its lowest corner 1 mm above the highest of the box below."""
    boxes, top = [], 0.0
    for _ in range(n):
        angle, x = rng.uniform(-0.02, 0.02), rng.uniform(-0.003, 0.003)
        y = top + 0.001 + _lowest(0.25, angle)
        boxes.append(_box(w, 0.5, 0.5, position=(x, y), angle=angle, restitution=0.0,
                          friction=0.5))
        top = y + _lowest(0.25, angle)
    return boxes


def _tilt(angle: float) -> float:
    """How far a box is turned from lying on a side (0 .. pi/4)."""
    a = angle % (math.pi / 2)
    return min(a, math.pi / 2 - a)


@pytest.mark.parametrize("seed", [7, 2, 3])
def test_jittered_column_settles_flat_or_topples(engine, seed: int) -> None:
    """The same column jittered (issue 34 item 4) settles as pymunk and Box2D do: flat (every
    box within 1e-6 rad of a side) and asleep with forces that hold it, or toppled; never
    asleep tilted. With the rest rule alone (contact_step = 0) the boxes freeze at their
    landing tilts (up to 0.02 rad)."""
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    _floor(w, 0.5, 0.0, half=5.0)
    boxes = _jittered_column(w, random.Random(seed))
    top = w.pose(boxes[-1])[1]
    w.step_to(4.0, events=False)
    asleep = [b for b in boxes if w.asleep(b)]
    if w.pose(boxes[-1])[1] > top - 0.5:      # standing: flat and asleep, held
        assert asleep == boxes
        assert max(_tilt(w.pose(b)[2]) for b in boxes) < 1e-6
    assert sleeping_residual(w) < CERTIFIED
    assert_apart(w)


def test_pyramid_of_ten_boxes_stands(engine) -> None:
    """Rows of 4, 3, 2 and 1 boxes, each row centred on the one below (0.02 m between boxes of a
    row): every box rests on two below (or the floor), sleeps certified and stays."""
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    _floor(w, 0.5, 0.0, half=5.0)
    boxes = []
    for row in range(4):
        for k in range(4 - row):
            x = (k - (3 - row) / 2) * 0.52
            boxes.append(_box(w, 0.5, 0.5, position=(x, 0.25 + row * (0.5 + 1e-6) + 1e-6),
                              restitution=0.0, friction=0.5))
    start = [w.pose(b) for b in boxes]
    w.step_to(2.0, events=False)
    assert all(w.asleep(b) for b in boxes)
    # as the column: 1e-6 m gaps closed and overlaps within the slop (measured: 1.02e-5 m)
    assert max(math.dist(p[:2], q[:2]) for p, q in zip(start, map(w.pose, boxes))) < 2e-5
    assert sleeping_residual(w) < CERTIFIED
    assert_apart(w)


def test_removing_the_support_wakes_what_it_held(engine) -> None:
    """A certified sleeper stays certified only while its support is there: remove the bottom
    box of a column of three and the two above fall (free fall: g t^2 / 2 before they land)."""
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    _floor(w, 0.5, 0.0, half=5.0)
    boxes = [_box(w, 0.5, 0.5, position=(0.0, 0.25 + k * (0.5 + 1e-6) + 1e-6), restitution=0.0,
                  friction=0.5) for k in range(3)]
    w.step_to(1.0, events=False)
    assert all(w.asleep(b) for b in boxes)
    y0 = w.pose(boxes[1])[1]
    w.remove(boxes[0])
    w.step_to(1.2, events=False)
    assert w.pose(boxes[1])[1] == pytest.approx(y0 - G * 0.2 ** 2 / 2, rel=1e-9)
    w.step_to(3.0, events=False)
    assert w.pose(boxes[1])[1] == pytest.approx(0.25, abs=1e-5)
    assert sleeping_residual(w) < CERTIFIED


# -- energy --------------------------------------------------------------------------------------

@pytest.mark.parametrize("seed", [2, 3])
def test_energy_rises_at_most_a_hop_per_body_and_tick(engine, seed: int) -> None:
    """docs/engine-contact.md: between ticks a solver body flies freely (its energy constant);
    a tick's inelastic solve raises the energy by at most m (|g| h / 2)^2 / 2 per body (a body
    stopped on a support leaves it at |g| h / 2 and lands again at the next tick). Sampled just
    after every tick of 5 s, the pile's energy never rises by more than that summed over the
    balls. (Before: segments at the tick's velocity with no gravity climbed, gaining
    m |g| v h by the next tick -- 1.2e-3 J between two of test_rest's samples, 50 ms apart --
    and a soft contact's solve treated solver neighbours as walls moving at their own
    velocity: a ball's kinetic energy doubled, 0.019 J.)"""
    assert CONTACT_STEP == H       # test_rest.py's pile ticks at the default step
    w = _rest_pile(engine, 40, seed)
    m, n = 0.05, 40
    bound = n * m * (G * H / 2) ** 2 / 2
    prev = w.energy(0.0)
    worst = -math.inf
    for k in range(1, int(5.0 / H)):
        w.step_to(k * H + 1e-9, events=False)
        e = w.energy()
        worst = max(worst, e - prev)
        prev = e
    assert worst <= bound      # measured: 4.1e-5 and 4.4e-5 J against 4.2e-4 (before: 1.3e-3)
    assert all(w.asleep(b.id) for b in w.bodies if b.kind == "dynamic")


# -- piles: every sleeper certified by the oracle --------------------------------------------------

def _pile(engine, seed: int, n: int, mu: float, e: float):
    rng = random.Random(seed)
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    for a, b in (((-1.5, 0), (1.5, 0)), ((-1.5, 0), (-1.5, 4)), ((1.5, 0), (1.5, 4))):
        w.add_segment(a, b, friction=mu, restitution=e)
    centres: list[tuple[float, float]] = []
    while len(centres) < n:
        x, y = rng.uniform(-1.2, 1.2), rng.uniform(0.3, 3.5)
        if all(math.hypot(x - a, y - b) > 0.45 for a, b in centres):
            centres.append((x, y))
    for k, (x, y) in enumerate(centres):
        if k % 2:
            _box(w, 0.3, 0.2, position=(x, y), angle=rng.uniform(0, 3), restitution=e, friction=mu)
        else:
            w.add_circle((x, y), rng.uniform(0.1, 0.2), restitution=e, friction=mu)
    return w


@settings(max_examples=10, deadline=None)
@given(seed=st.integers(0, 10_000), n=st.integers(2, 8), mu=st.sampled_from([0.0, 0.5]),
       e=st.sampled_from([0.0, 0.5]))
def test_every_sleeper_of_a_pile_is_held(engine, seed: int, n: int, mu: float, e: float) -> None:
    """Discs and boxes dropped into a bin settle for 5 s: whatever sleeps, the oracle finds
    non-negative forces inside the friction cones that hold it (the rest rule alone left discs
    asleep on nothing), and nothing overlaps beyond the tolerance."""
    w = _pile(engine, seed, n, mu, e)
    w.step_to(5.0, events=False)
    assert sleeping_residual(w) < CERTIFIED
    for b in w.bodies:
        if b.kind == "dynamic" and w.asleep(b.id):
            found, residual = w.certificate(b.id)   # inf: a moving body touches its island
            assert (found and residual < CERTIFIED) or residual == math.inf
    assert_apart(w)


def _dense_collapse(engine, n: int, mu: float, seed: int = 1):
    """bench/contact.py's scene: n discs (r = 0.15, e = 0.8 per contact, velocities in
    [-1, 1] m/s) dropped into a 10 m bin, 0.05 m apart at least."""
    rng = random.Random(seed)
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    e = math.sqrt(0.8)
    for a, b in (((0, 0), (10, 0)), ((0, 0), (0, 100)), ((10, 0), (10, 100))):
        w.add_segment(a, b, restitution=e, friction=mu)
    top = max(4.0, 2.5 * n * 0.3 ** 2 / 10 * 4)
    centres: list[tuple[float, float]] = []
    while len(centres) < n:
        x, y = rng.uniform(0.2, 9.8), rng.uniform(0.2, top)
        if all((x - a) ** 2 + (y - b) ** 2 > 0.35 ** 2 for a, b in centres):
            centres.append((x, y))
            w.add_circle((x, y), 0.15, velocity=(rng.uniform(-1, 1), rng.uniform(-1, 1)),
                         restitution=e, friction=mu)
    return w


@pytest.mark.parametrize("mu", [0.0, 0.5])
def test_dense_pile_of_200_discs_sleeps_certified(engine, mu: float) -> None:
    """The jammed pile (issue 34): before the slop every tick left a contact its solve could not
    meet, an exact event at the tick, ping-pong, and the wedge rule stopping all 200 once per
    tick; it never slept. Now by 12 s (they land by about 4 s) every disc sleeps, the oracle
    finds forces that hold each from the contacts within the slop, and no two overlap by more
    than the slop (exact geometry)."""
    w = _dense_collapse(engine, 200, mu)
    w.step_to(12.0, events=False)
    discs = [b.id for b in w.bodies if b.kind == "dynamic"]
    assert all(w.asleep(i) for i in discs)
    assert sleeping_residual(w, gap=w.contact_slop) < CERTIFIED   # contacts within the slop
    found, residual = w.certificate(discs[0])
    assert found and residual < CERTIFIED
    assert w.contact_slop == pytest.approx(1e-5)   # 10,000 tolerances
    assert_apart(w)
    assert all(0 < w.pose(i)[0] < 10 and w.pose(i)[1] > 0 for i in discs)


def test_frictionless_discs_never_turn(engine) -> None:
    """A frictionless contact's force passes through a circle's centre: no torque, so a disc
    that starts without spin keeps its angle exactly (the angular momentum about its centre is
    conserved), in the solver's ticks, its soft contacts and exact impacts alike. The rounding
    of cross(r, n) turned every disc of bench/contact.py's pile (up to 2e-12 rad/s)."""
    w = _dense_collapse(engine, 60, 0.0)
    discs = [b.id for b in w.bodies if b.kind == "dynamic"]
    w.step_to(3.0, events=False)
    assert any(w.solving(i) or w.asleep(i) for i in discs)
    assert [w.velocity(i)[2] for i in discs] == [0.0] * len(discs)
    assert [w.pose(i)[2] for i in discs] == [0.0] * len(discs)


# -- snapshots and scene files ---------------------------------------------------------------------

def test_snapshot_in_sustained_contact_reproduces_the_future(engine) -> None:
    """Pickled or copied while the box pivots on its corner (the solver holds it), the world goes
    on with the same events, bit for bit (the solver's bodies and warm-start impulses are saved)."""
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    _floor(w, 0.5, 0.0)
    b = _box(w, 0.5, 0.5, position=(0.0, _lowest(0.25, 0.6) + 0.01), angle=0.6, restitution=0.0,
             friction=0.5)
    w.step_to(0.2)
    assert w.solving(b)
    copied, pickled = copy.deepcopy(w), pickle.loads(pickle.dumps(w))
    future = w.step_to(3.0)
    assert future and future[-1].kind == "rest"     # it lands flat (the ticks), then sleeps
    assert abs(w.pose(b)[2]) < 1e-6
    for other in (copied, pickled):
        assert other.step_to(3.0) == future
        assert other.pose(b) == w.pose(b)           # bit for bit (ticks make no events)


def test_settling_pile_example_sleeps_certified(engine) -> None:
    """examples/scenes/settling-pile.toml (the picture in docs/engine-contact.md): 8 discs and
    8 boxes tumble into a bin and by its end (6.5 s: a disc rolls off a box tilted 6e-4 rad
    until 5.5 s) every one sleeps, each held by contact forces the oracle finds, none
    overlapping another beyond the tolerance."""
    from pathlib import Path

    from max2code.engine.scenefile import build_world, load

    scene = Path(__file__).resolve().parents[2] / "examples" / "scenes" / "settling-pile.toml"
    w = build_world(load(str(scene)))
    w.step_to(6.5, events=False)
    dynamic = [b.id for b in w.bodies if b.kind == "dynamic"]
    assert len(dynamic) == 16 and all(w.asleep(i) for i in dynamic)
    assert sleeping_residual(w) < CERTIFIED
    assert_apart(w)


def test_scene_file_turns_the_solver_on(engine, tmp_path) -> None:
    from max2code.engine.scenefile import SceneError, build_world, load

    text = """gravity = [0.0, -9.81]
[engine]
contact_step = %s
[[bodies]]
shape = "segment"
kind = "static"
points = [[-5, 0], [5, 0]]
[[bodies]]
shape = "box"
size = [0.5, 0.5]
position = [0.0, %r]
angle = 0.6
restitution = 0.0
"""
    good = tmp_path / "tip.toml"
    good.write_text(text % ("0.004166666666666667", _lowest(0.25, 0.6) + 0.01))
    w = build_world(load(good))
    w.step_to(3.0, events=False)
    assert abs(w.pose(1)[2]) < 0.02 and w.asleep(1)
    bad = tmp_path / "bad.toml"
    bad.write_text(text % ("-1.0", 1.0))
    with pytest.raises(SceneError, match=r"bad\.toml:3:\d+: error: engine\.contact_step: must not be negative"):
        load(bad)


def test_the_solver_is_on_by_default_and_0_turns_it_off(engine, tmp_path) -> None:
    """World() and a scene file without [engine] contact_step tick at 1/240 s: the tilted box
    tips flat. contact_step = 0 is the exact engine with the rest rule alone: it stays on its
    corner (issue 34's first item, kept as what the rest rule does)."""
    from max2code.engine.scenefile import build_world, load

    tilt = 0.6
    y = _lowest(0.25, tilt) + 0.01
    for step in (None, 0.0):
        w = engine.World(gravity=(0.0, -G), **({} if step is None else {"contact_step": step}))
        _floor(w, 0.5, 0.0)
        b = _box(w, 0.5, 0.5, position=(0.0, y), angle=tilt, restitution=0.0, friction=0.5)
        w.step_to(3.0, events=False)
        assert w.contact_slop == pytest.approx(1e-5 if step is None else 0.0)
        if step is None:
            assert abs(w.pose(b)[2]) < 0.02 and w.asleep(b)
        else:
            assert w.pose(b)[2] == pytest.approx(tilt, abs=1e-6)
    path = tmp_path / "tip.toml"
    path.write_text(f"""gravity = [0.0, -9.81]
[[bodies]]
shape = "segment"
kind = "static"
points = [[-5, 0], [5, 0]]
[[bodies]]
shape = "box"
size = [0.5, 0.5]
position = [0.0, {y!r}]
angle = {tilt}
restitution = 0.0
""")
    scene = load(path)
    assert scene.contact_step == 1 / 240
    w = build_world(scene)
    w.step_to(3.0, events=False)
    assert abs(w.pose(1)[2]) < 0.02 and w.asleep(1)


@pytest.mark.parametrize("step", [-1.0, math.inf, math.nan])
def test_world_refuses_a_bad_step(engine, step: float) -> None:
    with pytest.raises(engine.EngineError, match="contact_step"):
        engine.World(contact_step=step)


def test_next_time_includes_the_solvers_next_tick(engine) -> None:
    """World.next_time is when a server wakes: a tick changes the solver's bodies' motions (they
    fly freely under gravity between ticks), so it must come no later than the next tick. It
    used to count exact events and timers only: a server slept past the ticks, and its pages
    drew the compound example's dumbbell falling through the floor (tests/server/test_browser.py)."""
    w = engine.World(gravity=(0.0, -G), contact_step=H)
    w.add_segment((-5.0, 0.0), (5.0, 0.0), friction=0.5)
    box = _box(w, 0.5, 0.5, position=(0.0, 0.5), angle=0.6, friction=0.5, restitution=0.0)
    held, ticks = 0, 0
    for k in range(1, 60):
        w.step_to(0.01 * k, events=False)
        now = w.stats()["solver_ticks"]
        if now > ticks and not w.asleep(box):    # the solver holds it (it ticked): tipping
            held += 1
            assert w.next_time() <= w.time + H * (1 + 1e-9)
        ticks = now
    assert held > 5
