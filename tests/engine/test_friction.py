"""Coulomb friction at impacts: a spinning disc landing on a floor sticks or slips exactly as the
textbook impulse equations say, friction changes spin, never adds energy, and (between free
bodies) keeps momentum and angular momentum."""

from __future__ import annotations

import pytest

from .scenes import assert_apart, spinning_gas

M, R, V, E, W0 = 2.0, 0.5, 2.0, 0.5, 3.0   # mass, radius, landing speed, restitution, spin


def _land(engine, ball_mu: float, floor_mu: float):
    """A disc (I = m r^2 / 2) falling at V onto a floor, spinning W0 anticlockwise, no gravity:
    it lands at t = 0.5."""
    w = engine.World()
    w.add_segment((-5.0, 0.0), (5.0, 0.0), friction=floor_mu)
    b = w.add_circle((0.0, 1.5), R, velocity=(0.0, -V), omega=W0, mass=M, restitution=E,
                     friction=ball_mu)
    events = w.step_to(1.0)
    assert [(e.time, e.kind) for e in events] == [(0.5, "collision")]
    return w.velocity(b, 1.0)


def test_sticking_landing(engine) -> None:
    """Enough friction: the contact point stops sliding. Impulse equations at the contact point
    (arm (0, -r)): m dvx = P, I dw = r P, vx + w r = 0 after: P = -m w0 r / 3, so
    vx = -w0 r / 3 and w = w0 / 3 (needs |P| <= mu (1 + e) m v: mu >= 1/12 here)."""
    vx, vy, om = _land(engine, 1.0, 1.0)
    assert vx == pytest.approx(-W0 * R / 3, rel=1e-14)
    assert om == pytest.approx(W0 / 3, rel=1e-14)
    assert vy == pytest.approx(E * V, rel=1e-14)


@pytest.mark.parametrize("ball_mu,floor_mu", [(0.05, 0.05), (0.1, 0.025)])
def test_slipping_landing(engine, ball_mu: float, floor_mu: float) -> None:
    """Too little friction: the tangential impulse is mu times the normal one, J = (1 + e) m v,
    against the sliding (the contact point moves at +w0 r): vx = -mu J / m, w = w0 - 2 mu J /
    (m r). mu = sqrt(mu_ball mu_floor) = 0.05 in both cases."""
    mu = (ball_mu * floor_mu) ** 0.5
    J = (1 + E) * M * V
    vx, vy, om = _land(engine, ball_mu, floor_mu)
    assert vx == pytest.approx(-mu * J / M, rel=1e-14)
    assert om == pytest.approx(W0 - 2 * mu * J / (M * R), rel=1e-14)
    assert vy == pytest.approx(E * V, rel=1e-14)


@pytest.mark.parametrize("ball_mu,floor_mu", [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)])
def test_no_friction_keeps_the_spin(engine, ball_mu: float, floor_mu: float) -> None:
    assert _land(engine, ball_mu, floor_mu) == (0.0, E * V, W0)


def test_friction_never_adds_energy_and_keeps_momenta(engine) -> None:
    """Spinning circles, capsules and polygons with friction 0.6, elastic, free in space: the
    energy falls (or stays) at every collision, and the friction impulses, equal and opposite
    at one point, keep momentum and angular momentum."""
    w = spinning_gas(engine.World, 4, walls=False, friction=0.6)

    def totals(t):
        px = py = lz = 0.0
        for b in w.bodies:
            x, y, _ = w.pose(b.id, t)
            vx, vy, om = w.velocity(b.id, t)
            px, py = px + b.mass * vx, py + b.mass * vy
            lz += b.mass * (x * vy - y * vx) + b.inertia * om
        return px, py, lz

    energies = [w.energy(0.0)]
    w.on_collision(lambda world, ev: energies.append(world.energy()))
    before = totals(0.0)
    w.step_to(6.0)
    assert len(energies) > 5
    for a, b in zip(energies, energies[1:]):
        assert b <= a * (1 + 1e-13)
    assert energies[-1] < 0.99 * energies[0]      # and it does take some
    for a, b in zip(before, totals(6.0)):
        assert abs(a - b) <= 1e-12 * (1 + abs(a))


def test_friction_with_walls_never_overlaps_nor_gains(engine) -> None:
    w = spinning_gas(engine.World, 9, walls=True, friction=0.8)
    e = w.energy(0.0)
    for k in range(1, 61):
        w.step_to(k / 20, events=False)
        now = w.energy()
        assert now <= e * (1 + 1e-13)
        e = now
        assert_apart(w)


def test_negative_friction_refused(engine) -> None:
    w = engine.World()
    with pytest.raises(engine.EngineError, match="friction"):
        w.add_circle((0.0, 0.0), 1.0, friction=-0.1)
