"""The guess past complex roots: a step past a root (C's OVERSHOT) certified as a bracket, and
Newton's steps where Laguerre has no real one.

Laguerre's method from 0 converges monotonically to the first root when every root is real.
A complex pair near the first real root turns a step past it: p < 0 at the new iterate.  The
guess then reports a bracket -- a root in (0, x) -- which the Bernstein test on
(0, x (1 + 2^-20)] certifies as it does a converged guess, and the polish starts inside the
step.  Before, the steps went on to the right towards the next root, crept and gave up, and
the solve bisected with Taylor points.  Where complex roots leave Laguerre no real step (its
square root's argument negative: at 0 already, on NEWTON) and p falls, a Newton step takes its
place, twice at most, after which Laguerre often resumes; before, the guess gave up there.
Checked here:

* the vectors are what they claim: products of a complex pair, the first real root and a few
  more factors; the pure-Python guess (bit for bit C's:
  test_python_control_flow.py) overshoots on each, with the exact first root before the step's
  end;
* every runtime (the C driver, the Rust crate, Python's pure and C backends) answers every
  call right by the exact oracle (exact_roots.judge: integer arithmetic on the doubles);
* NEWTON's vectors have Laguerre's discriminant negative at 0 (exact arithmetic);
* the path: C settles each default solve of CERTIFIED and NEWTON by the certified guess -- one Bernstein
  test, no Taylor point, no derivative method, the polish from plain Newton -- and those of
  NOT_CERTIFIED (the pair within the test's reach) by the rest of the solver; Rust and Python
  take C's path on all of them (paths.assert_ports_take_c_path).
"""
from __future__ import annotations

from fractions import Fraction
from pathlib import Path
from typing import Sequence

import pytest

from . import cases
from . import exact_roots as ex
from . import paths
from .test_python_control_flow import counts_driver  # noqa: F401

Vector = tuple[tuple[float, ...], float]


def _vec(pair: tuple[str, str], first: str, real: Sequence[str] = (),
         pairs: Sequence[tuple[str, str]] = ()) -> Vector:
    """The complex pair (real part, imaginary part), the first positive root, other real roots
    and pairs (exact decimals: cases.poly_from_roots); tmax 10.  (A root at 4 comes with lead
    -1/4, the factor 1 - t/4: a scaling by a power of two and a sign, which leaves the solver's
    normalised polynomial, and so its path, as it is.)"""
    lead = "-0.25" if "4" in real else "1"
    return cases.poly_from_roots([first, *real], [pair, *pairs], lead), 10.0


# Laguerre steps past the first root, and (0, the step's end] holds it alone in the
# Bernstein basis: the certified guess settles the solve
CERTIFIED: list[Vector] = [
    _vec(("0.5", "0.5"), "1.25", ["-2", "-5"]),         # past 1.25 to 1.62
    _vec(("0.5", "0.5"), "1.25", ["-2", "-5", "4"]),    # the next root at 4
    _vec(("0.75", "0.5"), "1", ["-3"]),                 # degree 4
    _vec(("1", "0.5"), "0.875", ["4"]),
    _vec(("1", "0.125"), "0.875", ["-2", "-5"]),        # one rounding past 0.875
    _vec(("1", "0.125"), "1", ["4"]),                   # one rounding past 1
    # degree 8: two more pairs, one on each side
    _vec(("0.75", "0.5"), "1", ["4"], [("2", "1"), ("-3", "0.5")]),
    _vec(("0.5", "0.5"), "1.25", ["-4"], [("-1", "1"), ("-4", "0.5")]),
]
# the pair is inside the Bernstein test's reach: the bracket is not certified, and the solve
# goes on as when a guess gives up
NOT_CERTIFIED: list[Vector] = [
    _vec(("0.5", "0.25"), "1.25", ["4"]),
    _vec(("1", "0.25"), "1.5", ["-2", "-5"]),
    _vec(("0.75", "0.5"), "1", ["4"], [("-2", "0.5"), ("-4", "0.5")]),
]
VECTORS = CERTIFIED + NOT_CERTIFIED
# a complex pair nearer 0 than the first root: no real Laguerre step at 0
NEWTON: list[Vector] = [
    _vec(("0.05", "0.2"), "0.5", ["-2", "-5"]),
    _vec(("0.05", "0.2"), "1", ["-3"], [("-1", "1")]),
    _vec(("0.1", "0.2"), "0.3", ["4"]),
    _vec(("0.2", "0.2"), "0.5", ["-3"], [("-1", "1")]),
    _vec(("0.1", "0.1"), "0.3", ["-2", "-5"]),
]


def test_the_vectors_overshoot(monkeypatch: pytest.MonkeyPatch) -> None:
    assert {len(c) - 1 for c, _ in CERTIFIED} >= {4, 5, 6, 8}
    for (c, tmax), guesses in zip(VECTORS, paths.python_returns("speculate_first_root", VECTORS,
                                                                 monkeypatch)):
        guess = guesses[0]
        truth = ex.first_root(c, tmax)
        assert truth.kind == "simple", (c, tmax, truth)
        over, start = guess.over, guess.root  # type: ignore[attr-defined]
        # the guess's scale: the solver normalises c by a power of two, which leaves the
        # roots where they are
        assert over > 0 and start is not None, (c, guess)
        assert 0 < truth.hi < over, (c, float(truth.lo), over)


def test_no_real_laguerre_step_at_0() -> None:
    for c, _ in NEWTON:
        n, (c0, c1, c2) = len(c) - 1, (Fraction(x) for x in c[:3])
        # (n - 1) f^2 times the discriminant at 0, f = c0, p' = c1, p''/2 = c2: its sign does
        # not depend on the solver's scaling
        assert (n - 1) * c1 * c1 - 2 * n * c0 * c2 < 0, c


@pytest.mark.parametrize("runtime", ["c", "rust", "python", "python-c"])
def test_every_runtime_against_the_oracle(runtime: str, tmp_path: Path,
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    # right by the oracle, and a root found (each vector has one in its window)
    bad = [str(r) for r in paths.judged(runtime, VECTORS + NEWTON, tmp_path, monkeypatch)
           if not r.verdict.startswith("ok") or r.answer[0] != 1]
    assert not bad, f"{runtime}:\n" + "\n".join(bad)


def test_c_certifies_the_bracket(counts_driver: Path,  # noqa: F811 (the imported fixture)
                                 monkeypatch: pytest.MonkeyPatch) -> None:
    vecs = VECTORS + NEWTON
    for i, ((c, tmax), row) in enumerate(zip(vecs, paths.c_solves(counts_driver, vecs))):
        if i >= len(VECTORS):
            assert row.path == (1, 0, 0, 1), (c, tmax, row)
        elif i < len(CERTIFIED):
            # one Bernstein test, the polish: plain Newton first (from inside the step), then
            # the precise step(s)
            assert row.path == (1, 0, 0, 1), (c, tmax, row)
            assert row.plain >= 1 and row.precise >= 1, (c, tmax, row)
        else:
            # the failed certificate, then the whole window's test, and more
            assert row.status == 1 and row.bernstein >= 2 and row.points + row.derivative > 0, \
                (c, tmax, row)
    paths.assert_ports_take_c_path(counts_driver, vecs, monkeypatch)

