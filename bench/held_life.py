#!/usr/bin/env python3
"""How long a held body's segment could stay within the held bound, by its form.

    python bench/held_life.py [SCENE ...]    # default: tipping-box compound; printed

A body the contact solver holds is sent as a chord, a quadratic or (protocol 6) a cubic, and
re-sent when the truth would leave the bound E (docs/server.md, "Bodies the contact solver
holds"). What limits a segment's life: this records each held body's true motion at every
solver tick of the scene served exactly (a Room, waking at each queued event), then, from
every tick k on, how many ticks each form stays within E of that truth (x, y, and the angle
at the body's reach; checked at eight instants per tick, the free flight between ticks
included):

* oracle: the form least-squares fitted to the truth over the ticks ahead (it knows the
  future: an upper bound on any fit's life), grown until it leaves E;
* history: the form fitted as the room can, to the last M tick poses and the next tick's
  (the flight gets there), extrapolated; and a replay of sending it: re-sent when it leaves,
  at most every 4 ticks (the rate's 1/60 s), which counts the segments a held body costs.

Forms: Q quadratic, C cubic and D quartic in x, y and the angle; PQ and PC a rotation about a fixed
pivot P (pose = P + R(theta(s) - theta0)(c0 - P), theta quadratic or cubic in s, P fitted
by least squares), which a box tipping on its corner follows with no curvature error in its
position. Numbers in docs/server.md, "What limits a held segment's life".
"""
from __future__ import annotations

import math
import statistics
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from max2code.engine.scenefile import load  # noqa: E402
from max2code.server import reckon  # noqa: E402
from max2code.server.room import Room  # noqa: E402

RATE_TICKS = 4      # ticks of 1/240 s between messages at 60 a second
DEGREE = {"Q": 2, "C": 3, "D": 4, "PQ": 2, "PC": 3}   # each form's degree (in the angle, for P*)


def held_truth(name: str) -> tuple[Room, dict[int, list[tuple[float, ...]]]]:
    """The scene served exactly; each held body's motion from each solver tick it was held."""
    scene = load(ROOT / "examples" / "scenes" / f"{name}.toml")
    until = min(scene.until or 10.0, 10.0)
    clock = [0.0]
    room = Room("life", scene, (), clock=lambda: clock[0], tolerance=0.0)
    truth: dict[int, list[tuple[float, ...]]] = {}
    while room.failed is None and (t := room.next_wake()) <= until:
        clock[0] = t
        room.advance(t)
        motions, _ = room.world.motions()
        for i, m in enumerate(motions):
            if room.world.solving(i):
                flights = truth.setdefault(i, [])
                if not flights or flights[-1][0] < m[0]:
                    flights.append(m)
    return room, truth


def _poly(s: np.ndarray, v: np.ndarray, degree: int) -> np.ndarray:
    """Least-squares c_1 s + ... + c_n s^n through (s, v) (through 0 at s = 0)."""
    a = np.stack([s ** k for k in range(1, degree + 1)], 1)
    return np.linalg.lstsq(a, v, rcond=None)[0]


def _eval(c: np.ndarray, s: float | np.ndarray):
    return sum(ck * s ** (k + 1) for k, ck in enumerate(c))


def form(kind: str, s: np.ndarray, d: np.ndarray, now: tuple[float, float, float]):
    """The form fitted to poses d (x, y, angle less `now`) at times s from now: s -> pose."""
    degree = DEGREE[kind]
    if kind in ("Q", "C", "D"):
        cs = [_poly(s, d[:, k], degree) for k in range(3)]
        return lambda u: tuple(now[k] + _eval(cs[k], u) for k in range(3))
    ca = _poly(s, d[:, 2], degree)
    th = _eval(ca, s)
    c, sn = np.cos(th), np.sin(th)
    n = len(s)
    m = np.zeros((2 * n, 2))       # c(s) - c0 = (R - I) r0, r0 = c0 - P
    m[:n, 0], m[:n, 1], m[n:, 0], m[n:, 1] = c - 1, -sn, sn, c - 1
    r0 = np.linalg.lstsq(m, np.concatenate([d[:, 0], d[:, 1]]), rcond=None)[0]

    def pose(u):
        a = _eval(ca, u)
        cc, ss = math.cos(a), math.sin(a)
        return (now[0] + (cc - 1) * r0[0] - ss * r0[1], now[1] + ss * r0[0] + (cc - 1) * r0[1], now[2] + a)
    return pose


def life(flights, k: int, f, bound: float, reach: float, h: float, most: int = 200) -> float:
    """Ticks from tick k until f leaves the bound of the truth (or the body stops being held)."""
    t0 = flights[k][0]
    for j in range(k, min(len(flights), k + most)):
        a = flights[j][0]
        b = flights[j + 1][0] if j + 1 < len(flights) else a + h
        if b - a > 1.5 * h:
            return j - k
        for frac in np.linspace(0, 1, 9)[1:]:
            t = a + frac * (b - a)
            p, q = reckon.state_at(flights[j], t), f(t - t0)
            if max(abs(p[0] - q[0]), abs(p[1] - q[1]), abs(p[2] - q[2]) * reach) > bound:
                return (t - t0) / h
    return most


def oracle(flights, k: int, kind: str, bound: float, reach: float, h: float, most: int = 80) -> int:
    """The most ticks from k over which the form fitted to the truth ahead stays within bound."""
    best = 0
    for n in range(1, most):
        if k + n > len(flights) or flights[min(k + n, len(flights) - 1)][0] - flights[k][0] > (n + 0.5) * h:
            break
        ts = [flights[j][0] + f * h for j in range(k, k + n) for f in (0, .25, .5, .75)]
        p = np.array([reckon.state_at(flights[min(k + int((t - flights[k][0]) / h + 1e-9), len(flights) - 1)], t)[:3]
                      for t in ts])
        s = np.array(ts) - ts[0]
        f = form(kind, s[1:], p[1:] - p[0], tuple(p[0]))
        if max(max(abs(a - b) * (reach if c == 2 else 1) for c, (a, b) in enumerate(zip(f(u), q)))
               for u, q in zip(s, p)) > bound:
            break
        best = n
    return best


def from_history(flights, k: int, kind: str, m: int, h: float):
    """The form fitted as the room can at tick k: to the last m tick poses and the next one."""
    t0 = flights[k][0]
    now = reckon.state_at(flights[k], t0)[:3]
    past = range(max(0, k - m), k)
    s = np.array([flights[j][0] - t0 for j in past] + [h])
    p = np.array([flights[j][1:4] for j in past] + [reckon.state_at(flights[k], t0 + h)[:3]]) - np.array(now)
    if len(s) <= DEGREE[kind] + 1:
        chord = reckon.chord(flights[k], t0, h)
        return lambda u: reckon.state_at(chord, t0 + u)[:3]
    return form(kind, s, p, now)


def main() -> int:
    names = sys.argv[1:] or ["tipping-box", "compound"]
    for name in names:
        room, truth = held_truth(name)
        h = room.step
        bound = room.slop + 9.81 * h * h / 8
        for i, flights in truth.items():
            reach = room.reach[i]
            print(f"{name}, body {i} ({room.world.bodies[i].name}): held {len(flights)} ticks, "
                  f"bound {bound:.3g} m")
            for kind in ("Q", "C", "PQ", "PC"):
                lives = [oracle(flights, k, kind, bound, reach, h) for k in range(0, len(flights) - 1, 2)]
                print(f"  oracle {kind}: median {statistics.median(lives):g} ticks, "
                      f"from the first 60 ticks' starts {statistics.median(lives[:30]):g}")
            chord = lambda k: (lambda c: lambda u: reckon.state_at(c, c[0] + u)[:3])(  # noqa: E731
                reckon.chord(flights[k], flights[k][0], h))
            for kind, m in [("chord", 0)] + [(f, m) for f in ("Q", "C", "D", "PQ", "PC") for m in (4, 6, 12)]:
                k, lives = 0, []
                while k < len(flights) - 1:
                    f = chord(k) if kind == "chord" else from_history(flights, k, kind, m, h)
                    lives.append(life(flights, k, f, bound, reach, h))
                    k += max(RATE_TICKS, int(lives[-1]))
                print(f"  history {kind}{'' if kind == 'chord' else f' M={m}'}: {len(lives)} segments, "
                      f"median life {statistics.median(lives):.1f} ticks")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
