"""Step 0b: "no root in the window" by the first bound at 0, over [0, tmax], before preparation.

With tmax finite, no contact skin and degree >= 3, every runtime tests, right after reading
the coefficients, whether q (p less its rounding envelope) stays positive on all of
[0, tmax] by the lower bound from its coefficients (q(0) against every negative term, to
first or second order) -- the same test the interval solver starts with over [0, T] -- and
returns "no root" at once where it holds.  It is only tried where the preparation would keep
every term (no zero leading coefficient, none negligible by the exponents, spread in range),
so that the polynomial tested is the one the full path would solve.  Checked here:

* on windows with no root (all real roots beyond tmax or negative, complex pairs clear of the
  axis), C returns 0 and its cost accounting shows only the test's n multiply-adds in the
  preparation phase: nothing else ran;
* where a root lies just inside tmax, just beyond it, or the test must not be tried or must
  fail safely (tmax near the double range's ends, a spread beyond 2^1021, a zero or negligible
  leading term, p(0) = 0), every answer is right by the exact oracle (integer arithmetic on
  the doubles);
* the Rust crate and the pure-Python solver take C's path on all of them.
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


def _clear() -> list[Vector]:
    """No root in (0, tmax] that the bound shows: c_0 = +-1 times a scale, every other term
    at most 10^-0.5 / n of it over the window, of either sign (so the terms against c_0 add up
    to less than a third of it), and none below 10^-6 / n of it there (so none is negligible);
    degrees 3 to 16, windows from 10^-3 to 10^3."""
    rng = random.Random(2026_12_01)
    out: list[Vector] = []
    for degree in (3, 4, 5, 8, 8, 12, 16):
        for _ in range(3):
            tmax = 10 ** rng.uniform(-3, 3)
            scale = rng.choice((1, -1)) * 10 ** rng.uniform(-6, 6)
            against = rng.randint(1, degree)  # at least one sign change: else step 0 decides
            c = [scale] + [scale * (-1 if k == against else rng.choice((1, -1)))
                           * 10 ** rng.uniform(-6, -0.5) / degree / tmax ** k for k in range(1, degree + 1)]
            out.append((tuple(c), tmax))
    return out


CLEAR = _clear()

# Where the test must find nothing wrong to clear, or must not be tried.
EDGES: list[Vector] = [
    # a root just inside the window, and the same polynomial with the root just beyond it
    (cases.poly_from_roots([1.0, -2.0, -3.0, 5.0], (), lead=1.0), 1.0 + 2 ** -40),
    (cases.poly_from_roots([1.0, -2.0, -3.0, 5.0], (), lead=1.0), 1.0 - 2 ** -40),
    # tmax near the top of the double range: the bound overflows (the test fails safely)
    (cases.poly_from_roots([-1.0, -2.0, -3.0, 7.0], (), lead=1.0), 1e300),
    ((1.0, -1.0, 1.0, -1.0, 1e-300), 1e300),
    # tmax tiny: the terms of the bound underflow; still no root before 1
    (cases.poly_from_roots([1.0, -2.0, 3.0], (), lead=-1.0), 1e-300),
    # spread beyond 2^1021: not tried (the sliced path decides)
    ((1e-300, -1.0, 0.0, 1e300), 1e-200),
    ((1e-300, -1.0, 0.0, 1e300), 2.0),
    # a zero leading coefficient, and a leading term negligible over the window: not tried
    ((2.0, -3.0, 1.0, 0.0, 0.0), 0.9),
    ((2.0, -3.0, 1.0, 1e-30), 0.9),
    ((2.0, -3.0, 1.0, 1e-30), 1.5),
    # p(0) = 0: the next root after 0 (not tried)
    ((0.0, 2.0, -3.0, 1.0), 0.9),
    ((0.0, 2.0, -3.0, 1.0), 1.5),
    # q(0) beats the negative terms only to second order
    ((1.0, -2.0, 1.5, -1e-3), 1.0),
    # all coefficients but c0 negative: the bound decides at the window's end
    ((1.0, -0.25, -0.25, -0.25), 1.0),
    ((1.0, -0.25, -0.25, -0.25), 2.0),
]


def test_c_clears_at_once(counts_driver: Path) -> None:  # noqa: F811 (the imported fixture)
    rows = paths.c_rows(counts_driver, CLEAR)
    for (c, tmax), row in zip(CLEAR, rows):
        assert ex.first_root(c, tmax).kind == "none", (c, tmax)
        n = len(c) - 1
        # status 0, and only the test's multiply-adds, in the preparation phase
        assert row[0] == "0" and [int(x) for x in row[3:]] == [0, 0, 0, 0, 0, n, 0, 0, 0], \
            f"{row}: c={c!r}, tmax={tmax!r}"


@pytest.mark.parametrize("runtime", ["c", "rust", "python", "python-c"])
def test_answers_against_the_oracle(runtime: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    vecs = CLEAR + EDGES
    answers = paths.answers(runtime, vecs, tmp_path, monkeypatch)
    calls = paths.CALLS
    bad = []
    for i, (c, tmax) in enumerate(vecs):
        for j, (method, _, eps, _) in enumerate(calls):
            st, t, g = answers[len(calls) * i + j]
            verdict = ex.judge(c, tmax, st, t, g, eps)
            if not verdict.startswith("ok"):
                bad.append(f"{verdict}: {method} eps={eps} gave {(st, t, g)} for c={c!r}, tmax={tmax!r}")
    assert not bad, f"{runtime}:\n" + "\n".join(bad)
    # the root just inside the window is found, the one just beyond is not
    k = len(CLEAR)
    assert answers[len(calls) * k][0] == 1 and answers[len(calls) * (k + 1)][0] == 0


def test_ports_take_the_same_steps(counts_driver: Path,  # noqa: F811 (the imported fixture)
                                   monkeypatch: pytest.MonkeyPatch) -> None:
    paths.assert_ports_take_c_path(counts_driver, CLEAR + EDGES, monkeypatch)
