"""The Python API refuses the numbers scene files refuse (issue 33, items 4 and 5).

Scene files check every number against what the engine's arithmetic can hold
(max2code/engine/limits.py); World's arguments went to the core unchecked: a mass of 1e308 was
accepted and the first impact ended in `overflow:`, a NaN velocity or a string radius ("1",
turned into 1.0 by float()) was taken, and 10**400 ended in Python's OverflowError. Each hostile
value of each argument is now an EngineError naming the argument, and the world is as it was
before the call; each value at the limits is accepted and a bounded run ends without a
non-finite pose.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from max2code.engine import EngineError, Input, World

NAN, INF = math.nan, math.inf
# refused for every argument: not finite, past 1e30, below 1e-30 and not 0, not a real number
HOSTILE = [NAN, INF, -INF, 1e308, -1e308, 1e31, -1e31, 5e-324, -5e-324, 1e-31, 10**400,
           -10**400, True, "1", None]
BOX = [(-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2)]


def world(**kw) -> World:
    """A floor, a ball and a box (ids 0, 1, 2), a timer at 5 s, run to t = 0.1."""
    w = World(gravity=(0, -9.81), **kw)
    w.add_segment((-5, 0), (5, 0))
    w.add_circle((0, 1), 0.1, velocity=(1, 0), restitution=0.9)
    w.add_polygon(BOX, position=(1, 2), omega=1.0)
    w.add_timer(5.0)
    w.step_to(0.1)
    return w


def state(w: World) -> tuple:
    """What a refused call must leave as it was."""
    return (w.time, list(w.bodies), w.poses(), [w.velocity(b) for b in range(len(w.bodies))],
            [w.acceleration(b) for b in range(len(w.bodies))], w.next_time(), w.stats()["events"])


# (the argument's name in the message, the call with the value v in that argument,
#  whether -0.0 is allowed there)
CALLS = [
    ("position[0]", lambda w, v: w.add_circle((v, 1), 0.1), True),
    ("position[1]", lambda w, v: w.add_polygon(BOX, position=(0, v)), True),
    ("radius", lambda w, v: w.add_circle((0, 3), v, kind="static"), True),
    ("vertices[2][0]", lambda w, v: w.add_polygon([(0, 0), (1, 0), (v, 1)], position=(0, 3)),
     True),
    ("vertices[1][1]", lambda w, v: w.add_segment((0, 3), (1, v)), True),
    ("angle", lambda w, v: w.add_polygon(BOX, position=(0, 3), angle=v), True),
    ("velocity[0]", lambda w, v: w.add_circle((0, 3), 0.1, velocity=(v, 0)), True),
    ("velocity[1]", lambda w, v: w.add_circle((0, 3), 0.1, velocity=(0, v)), True),
    ("omega", lambda w, v: w.add_polygon(BOX, position=(0, 3), omega=v), True),
    ("gravity[1]", lambda w, v: w.add_circle((0, 3), 0.1, gravity=(0, v)), True),
    ("mass", lambda w, v: w.add_circle((0, 3), 0.1, mass=v), False),
    ("density", lambda w, v: w.add_polygon(BOX, position=(0, 3), density=v), False),
    ("inertia", lambda w, v: w.add_polygon(BOX, position=(0, 3), inertia=v), False),
    ("restitution", lambda w, v: w.add_circle((0, 3), 0.1, restitution=v), True),
    ("friction", lambda w, v: w.add_circle((0, 3), 0.1, friction=v), True),
    ("part 1 of 2: radius", lambda w, v: w.add_compound([([(0, 0)], 0.1), ([(1, 0)], v)],
                                                        position=(0, 3)), True),
    ("part 0 of 2: vertices[0][1]", lambda w, v: w.add_compound([([(0, v)], 0.1),
                                                                 ([(1, 0)], 0.1)],
                                                                position=(0, 3)), True),
    ("velocity[1]", lambda w, v: w.set_velocity(1, (0, v)), True),
    ("omega", lambda w, v: w.set_velocity(2, (0, 0), v), True),
    ("position[0]", lambda w, v: w.set_pose(1, (v, 2)), True),
    ("angle", lambda w, v: w.set_pose(2, (1, 2), v), True),
    ("acceleration[1]", lambda w, v: w.set_acceleration(1, (0, v)), True),
    ("mass", lambda w, v: w.set_mass(1, v), False),
    ("inertia", lambda w, v: w.set_mass(2, 1.0, v), False),
    ("impulse[0]", lambda w, v: w.apply_impulse(1, (v, 0)), True),
    ("point[1]", lambda w, v: w.apply_impulse(2, (1, 0), (1, v)), True),
    ("t", lambda w, v: w.add_timer(v), None),
    ("event.time", lambda w, v: w.add_input(Input(v, "key_down", "left")), None),
    ("t", lambda w, v: w.step_to(v), None),
    ("t", lambda w, v: w.pose(1, v), None),
    ("t", lambda w, v: w.poses(v), None),
    ("t", lambda w, v: w.energy(v), None),
    ("point[0]", lambda w, v: w.query_point((v, 0)), True),
    ("upper[1]", lambda w, v: w.query_box((0, 0), (1, v)), True),
    ("end[0]", lambda w, v: w.cast_ray((0, 0.5), (v, 0.5)), True),
    ("horizon", lambda w, v: w.first_contact(1, 2, v), None),
]



def method(call) -> str:
    """The World method a CALLS entry calls (its lambda's one attribute named like one)."""
    return next(n for n in call.__code__.co_names if hasattr(World, n))


# where None is the argument's default: a time of None is now, a set_pose angle of None keeps
# the angle, a mass or an inertia of None is derived from the shape
NONE_IS_DEFAULT = {("mass", "add_circle"), ("inertia", "add_polygon"), ("angle", "set_pose"),
                   ("inertia", "set_mass"), ("t", "pose"), ("t", "poses"), ("t", "energy")}
assert NONE_IS_DEFAULT <= {(name, method(call)) for name, call, _ in CALLS}

NOW = {call for name, call, _ in CALLS  # a body's state: a tiny magnitude is 0
       if name.split("[")[0] in ("position", "angle", "velocity", "omega", "gravity",
                                 "acceleration", "impulse")
       or "apply_impulse" in call.__code__.co_names}


def test_tiny_changes_now_are_zero(engine):
    """A body's state (add_body's position, angle, velocity, omega, gravity; set_velocity,
    set_pose, set_acceleration, apply_impulse) takes a magnitude below 1e-30 as 0 (sign kept)
    rather than refusing it: a game computes them every frame, and a damped spring's speed
    passes 1e-30 after some 70 time constants (PGE rebuilds its World from such speeds).
    Anything else out of range is refused."""
    w = world()
    w.set_velocity(1, (1e-31, -5e-324), 1e-40)
    assert w.velocity(1) == (0.0, 0.0, 0.0)
    w.set_acceleration(1, (5e-324, -9.81))
    assert w.acceleration(1) == (0.0, -9.81)
    w.set_pose(2, (1e-35, 2.0), -1e-300)
    assert w.pose(2) == (0.0, 2.0, 0.0)
    w.apply_impulse(1, (1e-31, 0.0))
    assert w.velocity(1) == (0.0, 0.0, 0.0)
    with pytest.raises(EngineError, match=r"^velocity\[0\]: 1e\+31 is too large"):
        w.set_velocity(1, (1e31, 0))
    b = w.add_circle((-1e-31, 3), 0.1, velocity=(5e-324, 0), omega=-1e-40, angle=1e-35)
    assert w.pose(b) == (0.0, 3.0, 0.0) and w.velocity(b) == (0.0, 0.0, 0.0)


WORLD_ARGS = [  # World(...)'s own; (name, keywords, -0.0 allowed)
    ("gravity[1]", lambda v: dict(gravity=(0, v)), True),
    ("gravity[0]", lambda v: dict(gravity=(v, 0)), True),
    ("tolerance", lambda v: dict(tolerance=v), False),
    ("cell_size", lambda v: dict(cell_size=v), True),
    ("rest_speed", lambda v: dict(rest_speed=v), True),
    ("collapse_time", lambda v: dict(collapse_time=v), True),
    ("contact_step", lambda v: dict(contact_step=v), True),
]


@pytest.mark.parametrize("value", HOSTILE, ids=repr)
@pytest.mark.parametrize("name, call, zero", CALLS, ids=[c[0] + ":" + str(k)
                                                           for k, c in enumerate(CALLS)])
def test_a_hostile_number_is_refused_by_name_and_changes_nothing(engine, name, call, zero,
                                                                 value):
    w = world()
    before = state(w)
    if value is None and (name, method(call)) in NONE_IS_DEFAULT:
        call(w, None)               # the default: now, unchanged, derived from the shape
        w.step_to(1.0)
        assert all(math.isfinite(c) for p in w.poses() for c in p)
        return
    if call in NOW and isinstance(value, float) and 0 < abs(value) < 1e-30:
        call(w, value)              # a change made now: taken as 0 (test_tiny_changes_now...)
        return
    with pytest.raises(EngineError) as exc:
        call(w, value)
    assert str(exc.value).startswith(name + ":"), str(exc.value)
    assert state(w) == before
    w.step_to(1.0)                      # and the world still runs
    assert all(math.isfinite(c) for p in w.poses() for c in p)


@pytest.mark.parametrize("name, call, zero", CALLS, ids=[c[0] + ":" + str(k)
                                                           for k, c in enumerate(CALLS)])
def test_minus_zero_where_zero_is_allowed(engine, name, call, zero):
    """-0.0 is 0: taken where 0 is a value of the argument (a position, a speed, a time),
    refused where the argument must be positive (a mass)."""
    w = world()
    if zero is False:
        before = state(w)
        with pytest.raises(EngineError, match="must be positive"):
            call(w, -0.0)
        assert state(w) == before
        return
    try:
        call(w, -0.0)
    except EngineError as exc:   # a body in the way, a time before now: the core's own rules
        assert not str(exc).startswith(name + ":"), str(exc)
    w.step_to(1.0)
    assert all(math.isfinite(c) for p in w.poses() for c in p)


@pytest.mark.parametrize("value", HOSTILE, ids=repr)
@pytest.mark.parametrize("name, kw, zero", WORLD_ARGS, ids=[a[0] for a in WORLD_ARGS])
def test_world_refuses_hostile_settings_by_name(engine, name, kw, zero, value):
    with pytest.raises(EngineError) as exc:
        World(**kw(value))
    assert str(exc.value).startswith(name + ":"), str(exc.value)


@pytest.mark.parametrize("value", [True, -1, 2**62 + 1, 10**400, 1.5, "10", NAN])
def test_max_events_is_a_whole_number_in_range(engine, value):
    with pytest.raises(EngineError, match="^max_events:"):
        World(max_events=value)


def test_the_issue_s_cases(engine):
    """The cases of issue 33: gravity 1e308 (52 s for 10 s of simulation once), mass 1e308
    (accepted, then `overflow:` at the first impact), omega 1e308; each refused at the call."""
    with pytest.raises(EngineError, match=r"^gravity\[1\]: -1e\+308 is too large .* at most "
                                          r"1e\+30"):
        World(gravity=(0, -1e308))
    w = World(gravity=(0, -9.81))
    w.add_segment((-5, 0), (5, 0))
    with pytest.raises(EngineError, match=r"^mass: 1e\+308 is too large"):
        w.add_circle((0, 2), 0.5, mass=1e308)
    with pytest.raises(EngineError, match=r"^omega: 1e\+308 is too large"):
        w.add_polygon(BOX, position=(0, 3), omega=1e308)
    big = [(-5, -5), (5, -5), (5, 5), (-5, 5)]                # area 100: 1e32 kg
    with pytest.raises(EngineError, match=r"^density: its mass \(density x area\) 1e\+32 is "
                                          r"out of the range"):
        w.add_polygon(big, position=(0, 20), density=1e30)
    assert len(w.bodies) == 1


def test_span_is_the_scene_files_rule(engine):
    """A body reaching farther than 2^45 tolerances from the origin is refused (the scene
    files' span rule); a larger tolerance takes it."""
    reach = 2.0 ** 45 * 1e-9
    w = World()
    w.add_circle((reach - 1.0, 0), 0.5, kind="static")      # reaches reach - 0.5
    with pytest.raises(EngineError, match="^position: the body reaches"):
        w.add_circle((reach, 0), 0.5, kind="static")
    with pytest.raises(EngineError, match="^position: the body reaches"):
        w.set_pose(0, (0, reach))
    assert len(w.bodies) == 1 and w.pose(0) == (reach - 1.0, 0.0, 0.0)
    World(tolerance=1e-3).add_circle((reach, 0), 0.5, kind="static")


LIMITS = [  # values at the limits: accepted, and a bounded run ends with finite poses
    lambda w: w.add_circle((0, 3), 0.1, velocity=(1e30, 0)),
    lambda w: w.add_circle((0, 3), 0.1, velocity=(0, -1e30)),
    lambda w: w.add_circle((0, 3), 0.1, velocity=(1e-30, 0)),
    lambda w: w.add_circle((0, 3), 0.1, mass=1e30),
    lambda w: w.add_circle((0, 3), 0.1, mass=1e-30),
    lambda w: w.add_circle((0, 3), 0.1, gravity=(0, -1e30)),
    lambda w: w.add_circle((0, 3), 0.1, gravity=(0, 1e-30)),
    lambda w: w.add_polygon(BOX, position=(0, 3), omega=1e30),
    lambda w: w.add_polygon(BOX, position=(0, 3), omega=-1e-30),
    lambda w: w.add_polygon(BOX, position=(0, 3), inertia=1e30),
    lambda w: w.add_circle((0, 3), 1e-30, kind="static"),
    lambda w: w.add_circle((0, 3), 0.1, restitution=1e-30, friction=1e30),
    lambda w: w.set_velocity(1, (1e30, 1e30), 1e30),
    lambda w: w.set_acceleration(1, (0, -1e30)),
    lambda w: w.set_mass(1, 1e30),
    lambda w: w.apply_impulse(1, (1e30, 0)),
    lambda w: w.add_timer(1e30),
    lambda w: w.first_contact(1, 2, 1e30),
    lambda w: w.query_box((-1e30, -1e30), (1e30, 1e30)),
    lambda w: w.cast_ray((-1e30, 0.5), (1e30, 0.5)),
]


@pytest.mark.parametrize("call", LIMITS)
def test_values_at_the_limits_are_accepted_and_run(engine, call):
    w = world(max_events=20000)
    call(w)
    try:
        w.step_to(1.0)
    except EngineError as exc:         # a named end (max_events, stuck, overflow), not a NaN
        assert str(exc), exc
    assert all(math.isfinite(c) for p in w.poses() for c in p)


@pytest.mark.parametrize("kw", [dict(gravity=(0, -1e30)), dict(tolerance=1e30),
                                dict(cell_size=1e30), dict(rest_speed=-1e30),
                                dict(collapse_time=1e-30), dict(contact_step=0.0)])
def test_world_settings_at_the_limits_run(engine, kw):
    w = World(max_events=20000, **kw)
    w.add_segment((-5, 0), (5, 0))
    w.add_circle((0, 1), 0.1)
    try:
        w.step_to(1.0)
    except EngineError as exc:
        assert str(exc), exc
    assert all(math.isfinite(c) for p in w.poses() for c in p)


NUMBERS = st.one_of(st.floats(), st.floats(-1e31, 1e31), st.floats(-1e-29, 1e-29),
                    st.sampled_from([0.0, -0.0, 1e30, -1e30, 1e-30, 1e308, 5e-324]))


@settings(max_examples=60, deadline=None, suppress_health_check=list(HealthCheck))
@given(g=NUMBERS, x=NUMBERS, vy=NUMBERS, omega=NUMBERS, mass=NUMBERS, r=NUMBERS)
@example(g=-9.81, x=0.0, vy=0.0, omega=0.0, mass=1e308, r=0.1)  # the issue's
def test_drawn_numbers_are_refused_or_run_finite(engine, g, x, vy, omega, mass, r):
    """Every call is either refused with a message, or a bounded run ends (at most in
    max_events or stuck: never an impulse past doubles, `overflow:`) with every pose finite:
    no NaN leaks. (The old API took mass 1e308 and ended in `overflow:`.)"""
    w = World(gravity=(0, -9.81), max_events=5000)
    w.add_segment((-5, 0), (5, 0))
    for add in (lambda: w.add_polygon(BOX, position=(x, 3), velocity=(1, vy), omega=omega,
                                      mass=mass),
                lambda: w.add_circle((x, 6), r, gravity=(0, g))):
        n = len(w.bodies)
        try:
            add()
        except EngineError as exc:   # an argument named, or a derived mass, a shape rule
            assert str(exc) and len(w.bodies) == n, exc
    try:
        w.step_to(1.0)
    except EngineError as exc:   # max_events or stuck; an impulse past doubles was refused
        assert str(exc) and not str(exc).startswith("overflow"), exc
    assert all(math.isfinite(c) for p in w.poses() for c in p)
