"""A touch ahead, found by the guess: Laguerre's linear convergence, then Newton on p'.

Laguerre's method converges to a double root only linearly, each step about 0.28 of the one
before (at degree 8); after three such ratios the guess turns to Newton on p' (the critical
point is a simple root of p'), and where p there is within 2^20 times the rounding bound and
the Bernstein test clears everything before it, a small interval around it is settled: by
the one-pass certificate of touch_critical (p convex there, one critical point), else by the
derivative method (test_touch_critical.py).  Before, the Budan-Fourier bisection approached a touch one halving per
two Taylor points (6.3 Taylor points a graze on the benchmark's grazes).  Checked here, on
polynomials (t - d)^2 g(t) rounded once, g with real roots only, beyond d or negative (none
nearer 0 than d: then Laguerre from 0 heads for d at once):

* the C runtime's answer is right by the exact oracle (integer arithmetic on the doubles):
  the touch at d with the graze flag, or -- where rounding split the double root into two
  real roots -- the first of them;
* its cost accounting shows no Taylor point, at most one derivative-method call (on the
  small interval, where the certificate cannot tell: on none of these) and one Bernstein test
  (on the interval before it; the whole window's test, which a touch ahead leaves undecided,
  does not run): the touch path settled every one (the bisection needed 3-9 Taylor points
  here);
* the Rust crate and the pure-Python solver take C's path and give its answers, bit for bit.
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


def _touches() -> list[Vector]:
    rng = random.Random(1_2_2026)
    out: list[Vector] = []
    for degree in (4, 6, 8, 8, 10, 12):
        for _ in range(4):
            d = 10 ** rng.uniform(-3, 3)
            beyond = [d * rng.uniform(1.5, 20) for _ in range(rng.randint(1, degree - 3))]
            negative = [-d * 10 ** rng.uniform(0, 2) for _ in range(degree - 2 - len(beyond))]
            lead = rng.choice((1, -1)) * 10 ** rng.uniform(-4, 4)
            tmax = INF if rng.random() < 0.5 else max(beyond) * rng.uniform(1.2, 4)
            out.append((cases.poly_from_roots([d, d, *beyond, *negative], (), lead=lead), tmax))
    return out


TOUCHES = _touches()


def test_c_takes_the_touch_path(counts_driver: Path) -> None:  # noqa: F811 (the imported fixture)
    rows = paths.c_solves(counts_driver, TOUCHES)
    bad, grazes, certified = [], 0, 0
    for (c, tmax), row in zip(TOUCHES, rows):
        st, t, graze = row.status, row.t, row.graze
        verdict = ex.judge(c, tmax, st, t, graze)
        points, derivative, bernstein = row.points, row.derivative, row.bernstein
        if st != 1 or not verdict.startswith("ok"):
            bad.append(f"{verdict}: {(st, t, graze)} for c={c!r}, tmax={tmax!r}")
        elif points or derivative > 1 or bernstein != 1:
            bad.append(f"{points} Taylor points, {derivative} derivative-method calls, {bernstein} "
                       f"Bernstein tests: c={c!r}, tmax={tmax!r}")
        grazes += graze
        certified += derivative == 0
    assert not bad, "\n".join(bad)
    assert certified == len(TOUCHES), certified
    # (the rest split into two roots when rounded: answered at the first of them, which
    # never_late finds where the touch between them would be late -- issue 33, item 11)
    assert grazes >= len(TOUCHES) // 4, grazes


def test_ports_take_the_same_steps(counts_driver: Path,  # noqa: F811 (the imported fixture)
                                   monkeypatch: pytest.MonkeyPatch) -> None:
    paths.assert_ports_take_c_path(counts_driver, TOUCHES, monkeypatch)
