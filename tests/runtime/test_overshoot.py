"""The guess's step past a root (C's OVERSHOT): certified as a bracket, not given up.

Laguerre's method from 0 converges monotonically to the first root when every root is real.
A complex pair near the first real root turns a step past it: p < 0 at the new iterate.  The
guess then reports a bracket -- a root in (0, x) -- which the Bernstein test on
(0, x (1 + 2^-20)] certifies as it does a converged guess, and the polish starts inside the
step.  Before, the steps went on to the right towards the next root, crept and gave up, and
the solve bisected with Taylor points.  Checked here:

* the vectors are what they claim: products of a complex pair, the first real root and a few
  more factors, exact in binary; the pure-Python guess (bit for bit C's:
  test_python_control_flow.py) overshoots on each, with the exact first root before the step's
  end;
* every runtime (the C driver, the Rust crate, Python's pure and C backends) answers every
  call right by the exact oracle (exact_roots.judge: integer arithmetic on the doubles);
* the path: C settles each default solve of CERTIFIED by the certified guess -- one Bernstein
  test, no Taylor point, no derivative method, the polish from plain Newton -- and those of
  NOT_CERTIFIED (the pair within the test's reach) by the rest of the solver; Rust and Python
  take C's path on all of them (paths.assert_ports_take_c_path).
"""
from __future__ import annotations

from fractions import Fraction
from pathlib import Path
from typing import Sequence

import pytest

from . import exact_roots as ex
from . import paths
from .test_python_control_flow import counts_driver  # noqa: F401

Vector = tuple[tuple[float, ...], float]
F = Fraction


def _product(factors: Sequence[Sequence[Fraction]]) -> tuple[float, ...]:
    """The coefficients (ascending) of the product, each exact as a double."""
    out = [F(1)]
    for f in factors:
        new = [F(0)] * (len(out) + len(f) - 1)
        for i, a in enumerate(out):
            for j, b in enumerate(f):
                new[i + j] += a * b
        out = new
    assert all(F(float(x)) == x for x in out), out
    return tuple(float(x) for x in out)


def _pair(a: Fraction, b: Fraction) -> list[Fraction]:
    """(t - a)^2 + b^2: the complex pair a +- ib."""
    return [a * a + b * b, -2 * a, F(1)]


def _root(r: Fraction) -> list[Fraction]:
    return [-r, F(1)]


def _vec(a: Fraction, b: Fraction, r: Fraction, *more: list[Fraction]) -> Vector:
    """The pair a +- ib, the first real root r, then the other factors; tmax 10."""
    return _product([_pair(a, b), _root(r), *more]), 10.0


NEG2, NEG5, POS4 = [F(2), F(1)], [F(5), F(1)], [F(1), F(-1, 4)]  # roots -2, -5 and 4
# Laguerre steps past the first root, and (0, the step's end] holds it alone in the
# Bernstein basis: the certified guess settles the solve
CERTIFIED: list[Vector] = [
    _vec(F(1, 2), F(1, 2), F(5, 4), NEG2, NEG5),          # past 1.25 to 1.62
    _vec(F(1, 2), F(1, 2), F(5, 4), NEG2, NEG5, POS4),    # the next root at 4
    _vec(F(3, 4), F(1, 2), F(1), [F(3), F(1)]),           # degree 4
    _vec(F(1), F(1, 2), F(7, 8), POS4),
    _vec(F(1), F(1, 8), F(7, 8), NEG2, NEG5),             # one rounding past 0.875
    _vec(F(1), F(1, 8), F(1), POS4),                      # one rounding past 1
    # degree 8: two more pairs, one on each side
    _vec(F(3, 4), F(1, 2), F(1), _pair(F(2), F(1)), _pair(F(-3), F(1, 2)), POS4),
    _vec(F(1, 2), F(1, 2), F(5, 4), _pair(F(-1), F(1)), _pair(F(-4), F(1, 2)), [F(4), F(1)]),
]
# the pair is inside the Bernstein test's reach: the bracket is not certified, and the solve
# goes on as when a guess gives up
NOT_CERTIFIED: list[Vector] = [
    _vec(F(1, 2), F(1, 4), F(5, 4), POS4),
    _vec(F(1), F(1, 4), F(3, 2), NEG2, NEG5),
    _vec(F(3, 4), F(1, 2), F(1), _pair(F(-2), F(1, 2)), _pair(F(-4), F(1, 2)), POS4),
]
VECTORS = CERTIFIED + NOT_CERTIFIED


def _guesses(vecs: Sequence[Vector], monkeypatch: pytest.MonkeyPatch) -> list[object]:
    """The pure-Python solver's guess (its first _speculate_first_root) on each vector."""
    import max2code_runtime as rt
    from max2code_runtime import solver

    seen: list[object] = []
    inner = solver._speculate_first_root

    def spy(*args: object) -> object:
        seen.append(inner(*args))  # type: ignore[arg-type]
        return seen[-1]
    monkeypatch.setattr(solver, "_speculate_first_root", spy)
    monkeypatch.setattr(rt, "_C", None)
    out = []
    for c, tmax in vecs:
        seen.clear()
        rt.first_root_status(list(c), tmax, "interval", 0.0)
        assert seen, (c, tmax)
        out.append(seen[0])
    monkeypatch.undo()
    return out


def test_the_vectors_overshoot(monkeypatch: pytest.MonkeyPatch) -> None:
    assert {len(c) - 1 for c, _ in CERTIFIED} >= {4, 5, 6, 8}
    for (c, tmax), guess in zip(VECTORS, _guesses(VECTORS, monkeypatch)):
        truth = ex.first_root(c, tmax)
        assert truth.kind == "simple", (c, tmax, truth)
        over, start = guess.over, guess.root  # type: ignore[attr-defined]
        # the guess's scale: the solver normalises c by a power of two, which leaves the
        # roots where they are
        assert over > 0 and start is not None, (c, guess)
        assert 0 < truth.hi < over, (c, float(truth.lo), over)


@pytest.mark.parametrize("runtime", ["c", "rust", "python", "python-c"])
def test_every_runtime_against_the_oracle(runtime: str, tmp_path: Path,
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    got = paths.answers(runtime, VECTORS, tmp_path, monkeypatch)
    bad = []
    for i, (c, tmax) in enumerate(VECTORS):
        for j, (method, _, eps, _) in enumerate(paths.CALLS):
            st, t, g = got[len(paths.CALLS) * i + j]
            verdict = ex.judge(c, tmax, st, t, g, eps)
            if not verdict.startswith("ok") or st != 1:
                bad.append(f"{verdict}: {method} eps={eps} gave {(st, t, g)} for c={c!r}, tmax={tmax!r}")
    assert not bad, f"{runtime}:\n" + "\n".join(bad)


def test_c_certifies_the_bracket(counts_driver: Path,  # noqa: F811 (the imported fixture)
                                 monkeypatch: pytest.MonkeyPatch) -> None:
    # STATUS T GRAZE PLAIN PRECISE POINTS DERIVATIVE BERNSTEIN MADDS0..3
    for i, ((c, tmax), row) in enumerate(zip(VECTORS, paths.c_rows(counts_driver, VECTORS))):
        st, points, derivative, bernstein = int(row[0]), int(row[5]), int(row[6]), int(row[7])
        if i < len(CERTIFIED):
            # one Bernstein test, the polish: plain Newton first (from inside the step), then
            # the precise step(s)
            assert (st, points, derivative, bernstein) == (1, 0, 0, 1), (c, tmax, row)
            assert int(row[3]) >= 1 and int(row[4]) >= 1, (c, tmax, row)
        else:
            # the failed certificate, then the whole window's test, and more
            assert st == 1 and bernstein >= 2 and points + derivative > 0, (c, tmax, row)
    paths.assert_ports_take_c_path(counts_driver, VECTORS, monkeypatch)

