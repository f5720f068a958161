"""The motion of bodies joined by damped springs, and proven bounds on it over a time window.

A spring joins the centres of mass of two bodies (either may be fixed); with r = p_b - p_a,
L = |r|, u = r / L and w = v_b - v_a, it pulls b with F = -(k (L - l0) + d L') u and a with -F
(L' = u . w: the damping acts along the spring only). Springs exert no torque, so a body's spin
is untouched. Between contacts the sprung bodies follow this ODE, which is not a polynomial:
the predictor (max2code.pge.springs) moves each body on its degree-2 Taylor polynomial over a
window and needs a proven bound on how far the real motion strays from it. With J >= |x'''|
on the window, the integral form of Taylor's remainder gives |x(t) - P2(t)| <= J (t - t0)^3 / 6
(a vector bound, not per component). `window_bounds` proves J:

1. An a priori enclosure (the Picard bootstrap): guess balls B(x0, Rx) for the positions and
   B(v0, Rv) for the velocities; bound every acceleration A over all states in them; if
   |v0| h + A h^2 / 2 <= Rx and A h <= Rv, no body can leave its balls during [t0, t0 + h]
   (at the first exit time the displacement would be at most those bounds, a contradiction),
   so the balls enclose the motion.
2. Over the enclosure, with W >= |w|, W' >= |w'|, L >= Lmin > 0 and |u'| = |w_perp| / L <= W / L:
   d/dt(-k (L - l0) u) = -k (w - l0 u') and d/dt(d L' u) = d (L'' u + L' u'), with
   |L''| = |u' . w + u . w'| <= W^2 / Lmin + W', so
   |dF/dt| <= k (W + l0 W / Lmin) + d (W' + 2 W^2 / Lmin), and |x_i'''| <= sum |dF/dt| / m_i.
   (l0 = 0 and d = 0, the linear spring, needs no Lmin: the body may pass through the anchor.)

The bounds are evaluated in doubles and then widened by the factor SAFETY, far more than the
rounding of these few operations (a relative 1e-15 each).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

SAFETY = 1.0 + 1e-9


@dataclass(frozen=True)
class Link:
    """One spring between ends a and b: indices into the sprung bodies, or None for a fixed
    end at `anchor_a` / `anchor_b`."""
    a: int | None
    b: int | None
    k: float
    d: float
    l0: float
    anchor_a: tuple[float, float] = (0.0, 0.0)
    anchor_b: tuple[float, float] = (0.0, 0.0)


@dataclass(frozen=True)
class System:
    """Sprung bodies (masses, own constant accelerations: gravity plus PGE's accel) and the
    springs between them. The state is y = [x0, y0, ..., vx0, vy0, ...] (n positions, then n
    velocities)."""
    masses: tuple[float, ...]
    gravity: tuple[tuple[float, float], ...]
    links: tuple[Link, ...]

    @property
    def n(self) -> int:
        return len(self.masses)

    def ends(self, link: Link, pos: np.ndarray, vel: np.ndarray):
        """(p_a, v_a, p_b, v_b) of a spring's ends."""
        zero = np.zeros(2)
        pa = pos[link.a] if link.a is not None else np.asarray(link.anchor_a, float)
        pb = pos[link.b] if link.b is not None else np.asarray(link.anchor_b, float)
        va = vel[link.a] if link.a is not None else zero
        vb = vel[link.b] if link.b is not None else zero
        return pa, va, pb, vb

    def tension(self, link: Link, pos: np.ndarray, vel: np.ndarray) -> tuple[np.ndarray, float, float]:
        """The force on end b, the spring's length and its rate of change."""
        pa, va, pb, vb = self.ends(link, pos, vel)
        r, w = pb - pa, vb - va
        length = math.hypot(r[0], r[1])
        if length == 0.0:  # no direction: only the linear part (-k r) is defined
            return -link.k * r, 0.0, 0.0
        u = r / length
        rate = float(u @ w)
        return -(link.k * (length - link.l0) + link.d * rate) * u, length, rate

    def accelerations(self, pos: np.ndarray, vel: np.ndarray) -> np.ndarray:
        acc = np.array(self.gravity, dtype=float).reshape(self.n, 2)
        m = np.asarray(self.masses)
        for link in self.links:
            f, _, _ = self.tension(link, pos, vel)
            if link.b is not None:
                acc[link.b] += f / m[link.b]
            if link.a is not None:
                acc[link.a] -= f / m[link.a]
        return acc

    def rhs(self, t: float, y: np.ndarray) -> np.ndarray:
        n = self.n
        pos, vel = y[:2 * n].reshape(n, 2), y[2 * n:].reshape(n, 2)
        return np.concatenate([vel.ravel(), self.accelerations(pos, vel).ravel()])

    def energy(self, y: np.ndarray) -> float:
        """Kinetic energy plus the springs' and the own accelerations' potential energies (kept
        by undamped springs between contacts; elastic contacts keep it too)."""
        n = self.n
        pos, vel = y[:2 * n].reshape(n, 2), y[2 * n:].reshape(n, 2)
        m = np.asarray(self.masses)
        e = 0.5 * float(np.sum(m * np.sum(vel * vel, axis=1)))
        e -= float(np.sum(m * np.sum(np.asarray(self.gravity).reshape(n, 2) * pos, axis=1)))
        for link in self.links:
            _, length, _ = self.tension(link, pos, vel)
            e += 0.5 * link.k * (length - link.l0) ** 2
        return e


@dataclass(frozen=True)
class Bounds:
    """Proven over the window: |x_i'''| <= jerk[i]; the enclosure radii used."""
    jerk: tuple[float, ...]
    rx: tuple[float, ...]
    rv: tuple[float, ...]

    def deviation(self, i: int, tau: float) -> float:
        """The proven distance between body i and its Taylor polynomial tau after the start."""
        return self.jerk[i] * tau ** 3 / 6.0 * SAFETY


def _acc_bounds(s: System, pos: np.ndarray, vel: np.ndarray, rx: Sequence[float],
                rv: Sequence[float]) -> list[float] | None:
    """sup |a_i| over the balls (None: a spring with a singular direction inside them)."""
    m = s.masses
    acc = [math.hypot(*g) for g in s.gravity]
    for link in s.links:
        pa, va, pb, vb = s.ends(link, pos, vel)
        grow = (rx[link.a] if link.a is not None else 0.0) + (rx[link.b] if link.b is not None else 0.0)
        wgrow = (rv[link.a] if link.a is not None else 0.0) + (rv[link.b] if link.b is not None else 0.0)
        length = math.hypot(*(pb - pa))
        lo, hi = max(0.0, length - grow), length + grow
        stretch = max(abs(hi - link.l0), abs(lo - link.l0))
        wmax = math.hypot(*(vb - va)) + wgrow
        f = (link.k * stretch + link.d * wmax) * SAFETY
        for end in (link.a, link.b):
            if end is not None:
                acc[end] += f / m[end]
    return acc


def window_bounds(s: System, y: np.ndarray, h: float) -> Bounds | None:
    """Proven jerk bounds over [t0, t0 + h] from the state y at t0, or None when no enclosure
    was found (or a spring may shrink to zero length where its direction matters): take a
    shorter window."""
    n = s.n
    pos, vel = y[:2 * n].reshape(n, 2), y[2 * n:].reshape(n, 2)
    a0 = s.accelerations(pos, vel)
    speed = [math.hypot(*v) for v in vel]
    acc0 = [math.hypot(*a) for a in a0]
    rx = [2.0 * (speed[i] * h + acc0[i] * h * h / 2) + 1e-300 for i in range(n)]
    rv = [2.0 * acc0[i] * h + 1e-300 for i in range(n)]
    for _ in range(12):
        acc = _acc_bounds(s, pos, vel, rx, rv)
        need_x = [(speed[i] * h + acc[i] * h * h / 2) * SAFETY for i in range(n)]
        need_v = [acc[i] * h * SAFETY for i in range(n)]
        if all(need_x[i] <= rx[i] and need_v[i] <= rv[i] for i in range(n)):
            break
        rx = [max(rx[i], 2.0 * need_x[i]) for i in range(n)]
        rv = [max(rv[i], 2.0 * need_v[i]) for i in range(n)]
    else:
        return None
    jerk = [0.0] * n
    for link in s.links:
        pa, va, pb, vb = s.ends(link, pos, vel)
        grow = (rx[link.a] if link.a is not None else 0.0) + (rx[link.b] if link.b is not None else 0.0)
        wgrow = (rv[link.a] if link.a is not None else 0.0) + (rv[link.b] if link.b is not None else 0.0)
        w = math.hypot(*(vb - va)) + wgrow
        wdot = (acc[link.a] if link.a is not None else 0.0) + (acc[link.b] if link.b is not None else 0.0)
        lmin = math.hypot(*(pb - pa)) - grow
        if link.l0 == 0.0 and link.d == 0.0:
            df = link.k * w
        elif lmin <= 0.0:
            return None
        else:
            df = link.k * (w + link.l0 * w / lmin) + link.d * (wdot + 2.0 * w * w / lmin)
        for end in (link.a, link.b):
            if end is not None:
                jerk[end] += df * SAFETY / s.masses[end]
    return Bounds(tuple(jerk), tuple(rx), tuple(rv))


def window_for(s: System, y: np.ndarray, budget: Sequence[float], h_max: float,
               h_min: float = 1e-12) -> tuple[float, Bounds]:
    """The longest window h <= h_max (halving, or the bound's own estimate) whose proven
    deviation stays within budget[i] for every body i."""
    h, h_min = h_max, min(h_min, h_max)
    while h >= h_min:
        b = window_bounds(s, y, h)
        if b is not None:
            worst = max((b.deviation(i, h) / budget[i] for i in range(s.n)), default=0.0)
            if worst <= 1.0:
                return h, b
            h = min(h / 2, h * 0.9 / worst ** (1 / 3))
        else:
            h /= 2
    raise ArithmeticError(f"springs: no window of at least {h_min:g} s keeps the motion within "
                          "its budget (a spring collapsing to zero length?)")
