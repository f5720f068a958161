"""No contact adds energy beyond the documented allowance (issue 33).

A static wall does no work, and two bodies pushing each other apart push as much as they are
pushed: the minimum parting speeds that end a Zeno chatter (the rest rule's a_n t_c / 2, the
contact solver's soft response at -acc h / 2, a_n the gap's curvature) come out of the pair's
own kinetic energy (response.c, part_within_energy). Only gravity's part may add energy: the
hop of docs/engine-contact.md, m (|g| h / 2)^2 / 2 per body and contact or tick (h > t_c by
default, so it covers the rest rule's m (g_n t_c / 2)^2 / 2 too). The allowance is computed
here from the bodies' masses, gravity and the documented defaults, not read from the engine.
"""

from __future__ import annotations

import math

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from max2code.engine.world import EngineError

from .scenes import engine_floats
from .test_compound import compound

T_C = 1e-3      # the rest rule's contact time (docs/engine.md, defaults)
H = 1 / 240     # the contact solver's step (docs/engine-contact.md, defaults)
WALL = ((0.0, 0.0), (0.0, 3.0))   # a thin static wall; the bodies are thrown at its lower end


@st.composite
def shape(draw):
    """One convex shape (a circle, capsule or polygon up to 0.5 across), or a compound."""
    kind = draw(st.sampled_from(["circle", "capsule", "polygon", "compound"]))
    size = draw(engine_floats(0.05, 0.25))
    if kind == "circle":
        return [([(0.0, 0.0)], size)]
    if kind == "capsule":
        return [([(-size, 0.0), (size, 0.0)], draw(engine_floats(size / 6, size / 2)))]
    if kind == "polygon":
        n = draw(st.integers(3, 6))
        return [([(size * math.cos(2 * math.pi * k / n), size * math.sin(2 * math.pi * k / n))
                  for k in range(n)], 0.0)]
    return draw(compound())


@st.composite
def throws(draw):
    """A shape 1.5 m below-left or below-right of the target, spinning at up to 3000 rad/s,
    thrown at it at 30 to 1000 m/s (within 0.3 rad of its centre): the target the thin wall's
    end (static), or -- with no wall -- a second shape at rest there, spinning or not."""
    phi = draw(engine_floats(-2.3, -0.85))
    speed = draw(st.sampled_from([30.0, 300.0, 1000.0]))
    heading = phi + math.pi + draw(engine_floats(-0.3, 0.3))
    thrown = dict(parts=draw(shape()), position=(1.5 * math.cos(phi), 1.5 * math.sin(phi)),
                  angle=draw(engine_floats(0.0, 6.3)),
                  velocity=(speed * math.cos(heading), speed * math.sin(heading)),
                  omega=draw(st.one_of(st.sampled_from([2000.0, -3000.0, 0.0]),
                                       engine_floats(-3000.0, 3000.0))),
                  restitution=draw(st.sampled_from([0.3, 0.1, 0.7, 1.0])))
    partner = None
    if draw(st.booleans()):
        partner = dict(parts=draw(shape()), position=(0.0, 0.0), angle=draw(engine_floats(0, 6.3)),
                       omega=draw(st.sampled_from([0.0, 500.0])),
                       restitution=draw(st.sampled_from([1.0, 0.7])))
    gravity = draw(st.sampled_from([(0.0, 0.0), (0.0, -9.81), (3.0, -50.0)]))
    return gravity, thrown, partner, min(1.0, 3.0 / speed + 0.02)


def hop(mass: float, gravity) -> float:
    """The documented energy gravity's part of a parting may add: m (|g| h / 2)^2 / 2."""
    return mass * (math.hypot(*gravity) * max(H, T_C) / 2) ** 2 / 2


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow],
          derandomize=True, database=None)   # (the same worlds each run: CI must not flicker)
@given(world=throws())
def test_no_contact_adds_energy_beyond_gravitys_hop(engine, world):
    """Shapes and compounds spinning at up to 3000 rad/s thrown at a thin static wall's end or
    at a second shape, with and without gravity: at every collision the world's energy is at
    most its start plus the hop allowance for every collision and solver tick so far (a named
    refusal, 'stuck', is allowed; the energy up to it is checked)."""
    gravity, thrown, partner, t_end = world
    w = engine.World(gravity=gravity)
    if partner is None:
        w.add_segment(*WALL)
    else:
        w.add_compound(partner.pop("parts"), **partner)
    w.add_compound(thrown.pop("parts"), **thrown)
    per_event = sum(hop(b.mass, gravity) for b in w.bodies if b.kind == "dynamic")
    e0 = w.energy()
    seen: list[tuple[float, float, int]] = []
    w.on_collision(lambda world_, ev: seen.append((ev.time, world_.energy(), len(seen) + 1)))
    try:
        w.step_to(t_end)
    except EngineError as error:
        assert "stuck" in str(error), error
    for t, e, k in seen:
        allowance = (k + t / H + 1) * per_event
        assert e <= e0 * (1 + 1e-9) + allowance + 1e-9, \
            f"energy {e0} -> {e} at t = {t} (collision {k}, allowance {allowance})"
