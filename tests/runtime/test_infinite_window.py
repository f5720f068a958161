"""tmax = inf finds every root a finite window finds (issue 33, item 1), in every runtime.

`1e-16 + t - 4.905 t^2` (a ball one ulp above a cell boundary, thrown up) gave "no root" with
tmax = inf and 0.2039 with tmax = 10, in C, Modula-2, Rust and Python alike: with an infinite
window the preparation compared the leading term against the Fujiwara bound of the *rest*
(1e-16 + t, whose root is -1e-16), found it negligible there and dropped it -- and with it the
root it makes.  The engine predicts cell crossings with tmax = inf, so balls fell through
floors.  Now an infinite window weighs the leading term over the bound on the positive roots
of the whole polynomial (the header, step 3), where a term that makes a root is never
negligible.

Checked here on the reproducer and on a family of such throws (a constant term within a few
ulps of 0, or the smallest subnormal, beside ordinary velocity and acceleration, degree 2 to
4), against the exact integer oracle (exact_roots) and against the same runtime's answer with
a finite window beyond the root (the same root within 4 ulps: the finite window takes the
solver's other early tests, and may polish to a neighbouring double).
"""
from __future__ import annotations

import math
import random
from fractions import Fraction
from pathlib import Path

import pytest

from . import every_runtime as er
from . import exact_roots as ex
from . import test_m2_runtime as m2

drivers = m2.drivers  # (the Modula-2 driver, for "m2")

REPRODUCER = (1e-16, 1.0, -4.905)
COUNT = 300


def _tiny(rng: random.Random, scale: float) -> float:
    """A positive constant term within a few ulps of 0 at the scale of the other terms (a
    height above the boundary that rounds to an ulp or less)."""
    return rng.choice((
        5e-324, 1e-16, math.ulp(scale) * rng.randint(1, 4), math.ulp(math.ulp(scale)),
        scale * 2.0 ** -rng.randint(40, 60),
    ))


def throws(count: int = COUNT, seed: int = 33) -> list[tuple[float, ...]]:
    """Bodies just above a boundary moving towards it after rising first: c_0 tiny, c_1 > 0,
    a negative leading coefficient (gravity, or a degree-4 contact polynomial's top term)."""
    rng = random.Random(seed)
    out = []
    while len(out) < count:
        v = 10 ** rng.uniform(-3, 3)
        g = 10 ** rng.uniform(-2, 2)
        deg = rng.choice((2, 2, 3, 4))
        c = [_tiny(rng, v), v] + [rng.uniform(-1, 1) * g for _ in range(deg - 2)] + [-g]
        out.append(tuple(c))
    return out


def _vectors() -> list[er.Vector]:
    """Each throw with tmax = inf and with tmax = twice its exact first root."""
    out: list[er.Vector] = [(REPRODUCER, math.inf), (REPRODUCER, 10.0)]
    for c in throws():
        truth = ex.first_root(c, math.inf)
        assert truth.kind != "none", c  # c_0 >= 0 > c_n, or a sign change: a root exists
        out += [(c, math.inf), (c, float(2 * truth.hi))]
    return out


VECTORS = _vectors()


@pytest.mark.parametrize("runtime", er.RUNTIMES)
def test_infinite_window_keeps_the_root(runtime: str, tmp_path: Path,
                                        monkeypatch: pytest.MonkeyPatch,
                                        request: pytest.FixtureRequest) -> None:
    m2_exe = request.getfixturevalue("drivers")[0] if runtime == "m2" else None
    got = er.answers(runtime, VECTORS, tmp_path, monkeypatch, m2_exe)
    st, t, _ = got[0]
    assert st == 1 and abs(Fraction(t) - ex.first_root(REPRODUCER, math.inf).hi) < Fraction(1, 10**15), got[0]
    assert got[0] == got[1], "tmax = inf and tmax = 10 differ on the reproducer"
    bad = []
    for k in range(0, len(VECTORS), 2):
        (c, _), (_, tmax) = VECTORS[k], VECTORS[k + 1]
        inf_answer, finite_answer = got[k], got[k + 1]
        verdict = ex.judge(c, math.inf, *inf_answer)
        same = finite_answer[0] == 1 and abs(inf_answer[1] - finite_answer[1]) <= 4 * math.ulp(
            finite_answer[1])
        if inf_answer[0] != 1 or not verdict.startswith("ok") or not same:
            bad.append(f"{verdict}: tmax=inf {inf_answer}, tmax={tmax!r} {finite_answer}, c={c!r}")
    assert not bad, f"{len(bad)} of {len(VECTORS) // 2 - 1}:\n" + "\n".join(bad[:8])


def test_the_judge_no_longer_excuses_the_drop() -> None:
    """exact_roots.judge wrote the old rule down as documented (a root that only the dropped
    leading term makes may be missed: "ok-lead-dropped"); now "no root" there is a miss."""
    assert ex.judge(REPRODUCER, math.inf, 0, math.nan, False) == "miss"
    assert ex.documented_reduction(REPRODUCER, math.inf) == REPRODUCER


# With tmax = inf a leading term is weighed over (0, K], K the bound on the positive roots
# (header, step 3): each vector with what every runtime must answer.
LEAD_CASES: tuple[tuple[tuple[float, ...], float | None], ...] = (
    # 3e-30 t^3 beside 3 t^2 (its other roots lie near -1e30): dropped, 0.75 stays
    ((-4.5, 3.75, 3.0, 3e-30), 0.75),
    ((-3.0, 8.5, -4.0, -2.5, 1.0, 0.0, 0.0, 0.0, 1e-30), 0.5),
    # no real root; the rest 1 - 1e-10 t has 1e10, beyond K = 2^-18: not a root
    ((1.0, -1e-10, 2.0**-14), None),
    # the leading term makes the root 8.1e229 and is kept
    ((-4386.296610043701, -8.87599604097008e96, 1.0897379656641521e-133), 8.1450737e229),
)


@pytest.mark.parametrize("runtime", er.RUNTIMES)
def test_negligible_lead_is_weighed_over_the_root_bound(
        runtime: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
        request: pytest.FixtureRequest) -> None:
    m2_exe = request.getfixturevalue("drivers")[0] if runtime == "m2" else None
    got = er.answers(runtime, [(c, math.inf) for c, _ in LEAD_CASES], tmp_path, monkeypatch, m2_exe)
    for (c, want), (st, t, graze) in zip(LEAD_CASES, got):
        assert ex.judge(c, math.inf, st, t, graze).startswith("ok"), (c, st, t)
        truth = ex.first_root(c, math.inf)
        if want is None:
            assert st == 0 and truth.kind == "none", (c, t)
        else:  # the root as written above, and as the exact oracle has it
            assert st == 1 and abs(t - want) <= 1e-7 * want, (c, st, t)
            assert truth.lo <= Fraction(t) * (1 + Fraction(1, 10**12)), (c, t, truth)
            assert Fraction(t) <= truth.hi * (1 + Fraction(1, 10**12)), (c, t, truth)


# A root half the least subnormal from 0 (drawn by the ulp class at WINDOW_FUZZ_COUNT=20000):
# 5e-324 - 2 t + t^2 has its first root at 2.47e-324, just above half of 5e-324, so it rounds
# to 5e-324.  The extreme-spread slicing found it and scaled it back with one ldexp, whose
# rounding of the halfway case ties to 0: every runtime said "no root", the root at 2 lost too.
SUBNORMAL_ROOTS = [((5e-324, -2.0, 1.0), math.inf), ((5e-324, -2.0, 1.0), 3.0),
                   ((5e-324, -3.0, 1.0, 0.5), math.inf), ((1e-323, -2.0, 1.0), math.inf),
                   ((5e-324, -1.0, 0.0, 0.0, 1.0), math.inf)]


@pytest.mark.parametrize("runtime", er.RUNTIMES)
def test_a_root_rounding_to_the_least_subnormal_is_found(
        runtime: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
        request: pytest.FixtureRequest) -> None:
    m2_exe = request.getfixturevalue("drivers")[0] if runtime == "m2" else None
    got = er.answers(runtime, SUBNORMAL_ROOTS, tmp_path, monkeypatch, m2_exe)
    bad = [f"{ex.judge(c, t, *a)}: {a} for c={c!r}, tmax={t!r}"
           for (c, t), a in zip(SUBNORMAL_ROOTS, got) if not ex.judge(c, t, *a).startswith("ok")]
    assert not bad, "\n".join(bad)
    assert [a[:2] for a in got[:2]] == [(1, 5e-324)] * 2
