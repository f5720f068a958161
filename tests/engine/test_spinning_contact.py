"""Fast-spinning bodies are met at the touch (README: "nothing tunnels"): hypothesis aims a
capsule or a convex polygon spinning at 300 to 8000 rad/s and flying at up to 1000 m/s at a
disc (itself moving and turning). The engine's first collision must come no later than the
exact first touch: at its time the two shapes overlap by at most 1e-6, and at 200 times before
it (the free motion, the engine's exact poses) they do not overlap at all -- both checked in
exact rational geometry (the fuzz test's oracle; the engine's geometry code is not used).
Found by tests/engine/tunnelling_long.py: a capsule at 5067 rad/s was met 3.8 mm deep.
"""

from __future__ import annotations

import math

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .test_no_tunnelling_fuzz import too_close, world_points
from .scenes import engine_floats

SAMPLES = 200


@st.composite
def spinner(draw) -> dict:
    """A capsule or a (stretched regular) polygon at most 0.2 across, fast and fast-spinning."""
    size = draw(engine_floats(0.02, 0.1))
    if draw(st.booleans()):
        r = draw(engine_floats(0.005, size / 2))
        verts, radius = [(-size + r, 0.0), (size - r, 0.0)], r
    else:
        n = draw(st.integers(3, 6))
        stretch = draw(engine_floats(0.5, 1.0))
        verts = [(size * math.cos(2 * math.pi * k / n), stretch * size * math.sin(2 * math.pi * k / n))
                 for k in range(n)]
        radius = 0.0
    return dict(vertices=verts, radius=radius, angle=draw(engine_floats(0, 2 * math.pi)),
                omega=draw(engine_floats(300, 8000)) * draw(st.sampled_from([-1, 1])))


@st.composite
def scenes(draw):
    """(spinner, disc, horizon): the spinner starts 0.3-2 m from the disc, heading at it within
    a lateral miss of the disc's radius plus its own size (a hit, a graze or a near miss)."""
    body = draw(spinner())
    disc_r = draw(engine_floats(0.02, 0.3))
    dist = draw(engine_floats(0.3, 2.0)) + disc_r
    bearing = draw(engine_floats(0, 2 * math.pi))
    speed = draw(engine_floats(50, 1000))
    miss = draw(engine_floats(-1, 1)) * (disc_r + 0.1)
    ux, uy = math.cos(bearing), math.sin(bearing)
    body.update(position=(-dist * ux - miss * uy, -dist * uy + miss * ux),
                velocity=(speed * ux, speed * uy), mass=0.01, inertia=1e-5)
    dv = draw(engine_floats(0, 100))
    dv = dv if dv > 1e-20 else 0.0  # dv cos(3 bearing) stays 0 or above the API's 1e-30
    disc = dict(vertices=[(0.0, 0.0)], radius=disc_r, position=(0.0, 0.0),
                velocity=(dv * math.cos(3 * bearing), dv * math.sin(3 * bearing)),
                omega=draw(st.sampled_from([0.0, -40.0])), mass=0.1, inertia=1e-3)
    return body, disc, 2 * dist / speed


def shape(w, i, t):
    return world_points(w.bodies[i].vertices, w.pose(i, t)), w.bodies[i].radius


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scene=scenes())
def test_a_fast_spinner_is_met_at_the_touch(engine, scene):
    body, disc, horizon = scene
    w = engine.World()
    a, b = w.add_body(**body), w.add_body(**disc)
    first = w.first_contact(a, b, horizon)
    until = horizon if first is None else first
    # before the first contact the motion is free: no overlap (beyond 1e-6) at any sample
    for k in range(SAMPLES + 1):
        t = until * k / SAMPLES
        assert not too_close(*shape(w, a, t), *shape(w, b, t)), \
            f"overlap at t = {t}, before the engine's first contact at {first}"
    # the world's loop (broad phase, cells) meets them at the same touch
    late: list[str] = []

    def at_contact(world, ev) -> None:
        if not late and too_close(*shape(w, a, ev.time), *shape(w, b, ev.time)):
            late.append(f"overlap at the collision at t = {ev.time} (first_contact: {first})")

    w.on_collision(at_contact)
    w.step_to(horizon)
    assert not late, late[0]
