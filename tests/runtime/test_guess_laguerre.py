"""The guess at the first root: Laguerre's method from 0 settles real-rooted polynomials alone.

Once the cheap exits at 0 fail, every runtime first guesses the first root and certifies the
guess by Descartes' rule in the Bernstein basis on (0, r (1 + 2^-20)]; only when that fails do
the same rule on the whole window, Taylor shifts (Budan-Fourier points) and the derivative
method start.  The
guess is Laguerre's method from 0, each step taken to the right: for a polynomial whose roots
are all real it converges monotonically to the first positive root from there, however far
the other roots or the window reach.  Newton from where the control polygon crosses 0 (the
guess before) started near the middle of a window that is many times the first root, crept
towards it a step of about x / n at a time and often gave up or reached a later root.

Checked here, on real-rooted polynomials of degrees 4 to 16 with two or more positive roots
in the window, the first one 2 to 30 times below the next, no negative root nearer 0 than the
first positive one, and the window from 1.5 times the last positive root to infinite:

* the C runtime's first root is right by the exact oracle (integer arithmetic on the doubles),
  and its cost accounting (-DM2C_COUNT) shows no Taylor point, no derivative-method call and
  one Bernstein test: the certified guess settled every one of them (Newton from the control
  polygon needed Taylor points on 13 of these 40, all at degree 8 and above);
* Rust's counters and roots equal C's, and so do the pure-Python solver's events and answers
  (bit for bit: the ports take the same steps).
"""
from __future__ import annotations

import random
from pathlib import Path

import pytest

from . import cases, paths
from . import exact_roots as ex
from .test_python_control_flow import counts_driver  # noqa: F401

INF = float("inf")
Vector = tuple[tuple[float, ...], float]


def _vectors() -> list[Vector]:
    """Real roots only: the first positive one r, 1 to 4 more 2-30 times beyond each other, the
    rest negative, 1 to 1000 times r away from 0 (a negative root much nearer 0 than r slows
    Laguerre from 0: it then creeps, the steps growing by 1.5-3 times each, and gives up; the
    guess is then dropped, as Newton's was); the window infinite (Fujiwara's bound, far beyond
    the last root) or 1.5-20 times the last positive root."""
    rng = random.Random(20261201)
    out: list[Vector] = []
    for degree in (4, 8, 12, 16):
        for _ in range(10):
            r = 10 ** rng.uniform(-3, 3)
            positive = [r]
            for _ in range(rng.randint(1, min(4, degree - 1))):
                positive.append(positive[-1] * rng.uniform(2, 30))
            negative = [-r * 10 ** rng.uniform(0, 3) for _ in range(degree - len(positive))]
            lead = 10 ** rng.uniform(-4, 4) * rng.choice((1, -1))
            tmax = INF if rng.random() < 0.5 else positive[-1] * rng.uniform(1.5, 20)
            out.append((cases.poly_from_roots(positive + negative, (), lead=lead), tmax))
    return out


VECTORS = _vectors()


def test_c_settles_by_the_guess(counts_driver: Path) -> None:  # noqa: F811 (the imported fixture)
    rows = paths.c_solves(counts_driver, VECTORS)
    bad = []
    for (c, tmax), row in zip(VECTORS, rows):
        st, t, graze = row.status, row.t, row.graze
        verdict = ex.judge(c, tmax, st, t, graze)
        points, derivative, bernstein = row.points, row.derivative, row.bernstein
        if st != 1 or not verdict.startswith("ok"):
            bad.append(f"{verdict}: {(st, t, graze)} for c={c!r}, tmax={tmax!r}")
        elif points or derivative:
            bad.append(f"{points} Taylor points, {derivative} derivative-method calls: c={c!r}, tmax={tmax!r}")
        # the guess's certificate, and not the whole window's test (two or more roots there)
        elif bernstein != 1:
            bad.append(f"{bernstein} Bernstein tests: c={c!r}, tmax={tmax!r}")
    assert not bad, "\n".join(bad)


def test_ports_take_the_same_steps(counts_driver: Path,  # noqa: F811 (the imported fixture)
                                   monkeypatch: pytest.MonkeyPatch) -> None:
    paths.assert_ports_take_c_path(counts_driver, VECTORS, monkeypatch)
