"""The pure-Python runtime (runtime/python/max2code_runtime) against the
shared hard cases and random polynomials -- the same judge and the same
bounds as the C runtime, except that Python has no GSL method."""
from __future__ import annotations

import math
import os
import sys
from pathlib import Path

import pytest

from . import cases

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "runtime" / "python"))
import max2code_runtime as rt  # noqa: E402

RANDOM_COUNT = int(os.environ.get("M2C_RANDOM_CASES", "3000"))
ALL = cases.all_cases()
PY_METHODS = list(rt.METHODS)

Result = tuple[int, float, bool]


@pytest.mark.parametrize("method", PY_METHODS)
@pytest.mark.parametrize("case", ALL, ids=[c.name for c in ALL])
def test_case(case: cases.Case, method: str) -> None:
    st, t, g = rt.first_root_status(case.coeffs, case.tmax, method)
    why = cases.judge(case, method, st, t, g)
    assert why is None, f"{case.name} [{method}]: {why}"


def test_first_root_contract() -> None:
    assert rt.first_root(cases.KAHAN) == 1.0
    assert rt.first_root([1.0, math.nan]) is None  # invalid -> None
    assert rt.first_root([1.0, 1.0]) is None  # root -1: none
    assert rt.first_root([-1.0, 1.0], tmax=0.5) is None
    assert rt.first_root([-1.0, 1.0], tmax=1.0) == 1.0
    assert rt.first_root_status([1.0] * 10) == (-1, pytest.approx(math.nan, nan_ok=True), False)
    assert rt.first_root_status([], 1.0)[0] == -1
    assert rt.first_root_status([-1.0, 1.0], 1.0, method="gsl")[0] == -1  # no GSL in Python
    assert rt.first_root_status(["x"], 1.0)[0] == -1


def test_graze_flag_and_nograze() -> None:
    """A touch is reported flagged; without the check it is skipped."""
    c = cases.poly_from_roots(["1", "1", "5"], [("0", "1")])
    c = (c[0] * (1 + 2.0**-52),) + c[1:]  # no exact zero at the touch
    st, t, g = rt.first_root_status(c)
    assert st == 1 and g and abs(t - 1) < 1e-7
    st, t, g = rt.first_root_status(c, method="interval-nograze")
    assert st == 1 and abs(t - 5) < 1e-12 and not g


def test_python_matches_c_algorithm_on_kahan_discriminant() -> None:
    """Dekker's two-product gives the exact error fma would: the corrected
    discriminant of Kahan's quadratic is exactly h^2 - a c = 1 (scaled)."""
    from max2code_runtime.solver import quad_roots

    roots, disc = quad_roots(94906266.375, -2 * 94906267.375, 94906268.375)
    assert roots[0] == 1.0
    assert roots[1] == pytest.approx(1.0000000210734243, rel=4e-16)
    assert disc > 0


# Same kappa-relative bounds as for C (see test_c_runtime.random_bound).
def test_random() -> None:
    results = [(case, method, rt.first_root_status(case.coeffs, case.tmax, method))
               for case in cases.random_cases(RANDOM_COUNT) for method in PY_METHODS]
    bad = list(cases.random_failures(results))
    assert not bad, f"{len(bad)} failures, first: " + "\n".join(bad[:10])


def test_report_worst_errors(capsys: pytest.CaptureFixture[str]) -> None:
    """Prints the worst relative error per family and method (run with -s)."""
    results = {(c.name, m): rt.first_root_status(c.coeffs, c.tmax, m) for c in ALL for m in PY_METHODS}
    table = cases.format_worst(cases.worst_errors(results), "Python runtime: worst relative error")
    with capsys.disabled():
        print("\n" + table)
