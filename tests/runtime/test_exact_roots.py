"""The exact first-root oracle (exact_roots.py) against the mpmath/Sturm oracle of cases.py on
ordinary polynomials, and against roots known in closed form at the extremes, where mpmath
cannot go (a root beyond DBL_MAX, below the smallest subnormal, multiple roots)."""
from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import pytest

from . import cases
from . import exact_roots as ex


def _contains(truth: ex.Truth, x: mpmath.mpf, rel: float = 2.0**-70) -> bool:
    with mpmath.workdps(80):
        lo = mpmath.mpf(truth.lo.numerator) / truth.lo.denominator
        hi = mpmath.mpf(truth.hi.numerator) / truth.hi.denominator
        return lo * (1 - rel) <= x <= hi * (1 + rel)


def _ordinary() -> list[tuple[str, tuple[float, ...], float]]:
    out = [(c.name, tuple(c.coeffs), c.tmax) for c in cases.all_cases() if c.expect != "invalid"]
    out += [(f"random{i}", r.coeffs, r.tmax) for i, r in enumerate(cases.random_cases(150))]
    return out


@pytest.mark.parametrize("name,coeffs,tmax", _ordinary(), ids=lambda v: v if isinstance(v, str) else "")
def test_same_first_root_as_mpmath(name: str, coeffs: tuple[float, ...], tmax: float) -> None:
    o = cases.oracle(coeffs, tmax)
    truth = ex.first_root(coeffs, tmax)
    if o.root is None:
        assert truth.kind == "none", (truth.kind, float(truth.hi))
        return
    assert truth.kind != "none" and _contains(truth, o.root), (o.root, float(truth.lo), float(truth.hi))
    if o.kind == "simple" and truth.kind == "simple":
        assert math.isclose(truth.kappa, o.kappa, rel_tol=1e-6)


def test_known_roots_at_the_extremes() -> None:
    inf = math.inf
    # issue 12: the root is (1e200 / 1e100)^(1/3) within 1e-160 relative (the rest is tiny there)
    t = ex.first_root((1e-200, 1e200, -0.5, 1e-200, -1e100), inf)
    with mpmath.workdps(80):
        root = mpmath.cbrt(mpmath.mpf(1e200) / mpmath.mpf(1e100))
    assert t.kind == "simple" and _contains(t, root, 1e-150)
    # the root DBL_MAX / 2^-1074 = 2^2098 (1 - 2^-53), beyond every double
    dmax = 1.7976931348623157e308
    t = ex.first_root((-dmax, 5e-324), inf)
    assert t.kind == "simple" and t.lo <= Fraction(dmax) / Fraction(5e-324) <= t.hi
    assert ex.judge((-dmax, 5e-324), inf, 0, math.nan, False) == "ok-not-representable"
    assert ex.judge((-dmax, 5e-324), inf, 1, dmax, False) not in ("ok-root",)
    # a root below the smallest subnormal: 2^-1074 / 2^1023 (not representable)
    t = ex.first_root((-5e-324, 2.0**1023), inf)
    assert t.lo == t.hi == Fraction(5e-324) / 2**1023 or t.lo <= Fraction(5e-324) / 2**1023 <= t.hi
    assert ex.judge((-5e-324, 2.0**1023), inf, 0, math.nan, False) == "ok-not-representable"
    # a subnormal root: found to the last bit is right, a later root is not
    assert ex.judge((-1e-320, 1.0), inf, 1, 1e-320, False) == "ok-root"
    assert ex.judge((-1e-320, 1.0), inf, 1, 2e-320, False) == "wrong-late"
    # roots at 1e-200 and 1e200 in one polynomial: (t - 2^-664)(t - 2^664)
    a, b = 2.0**-664, 2.0**664
    c = (a * b, -(a + b), 1.0)
    assert ex.judge(c, inf, 1, a, False) == "ok-root"
    assert ex.judge(c, inf, 1, b, False) == "wrong-late"
    assert ex.judge(c, inf, 0, math.nan, False) == "miss"
    assert ex.judge(c, 2.0**-665, 0, math.nan, False) == "ok-none"
    assert ex.judge(c, inf, 1, a * (1 + 2.0**-45), False) == "ok-root"
    assert ex.judge(c, inf, 1, a * (1 - 2.0**-30), False) == "wrong-early"


def test_multiple_roots() -> None:
    inf = math.inf
    # (t - 1)^2: a touch; status 0 is allowed (rounding can lift it), t = 1 is right
    assert ex.first_root((1.0, -2.0, 1.0), inf).kind == "cluster"
    assert ex.judge((1.0, -2.0, 1.0), inf, 0, math.nan, False) == "ok-cluster-missed"
    assert ex.judge((1.0, -2.0, 1.0), inf, 1, 1.0, True) == "ok-cluster"
    # (t - 1)^3 crosses zero: status 0 is a miss
    assert ex.judge((-1.0, 3.0, -3.0, 1.0), inf, 0, math.nan, False) == "miss"
    # (t - 3)^2 (t - 5): the cluster at 3 first, not the simple root at 5
    c = (-45.0, 39.0, -11.0, 1.0)
    assert ex.first_root(c, inf).kind == "cluster"
    assert ex.judge(c, inf, 1, 5.0, False) == "wrong-late"
    # no positive root at all; none within a window before the first root
    assert ex.first_root((1.0, 2.0, 1.0), inf).kind == "none"
    assert ex.judge((1.0, 2.0, 1.0), inf, 1, 1.0, False) == "false"
    assert ex.judge((-6.0, 5.0, -1.0), 1.5, 0, math.nan, False) == "ok-none"


def test_documented_lead_rule() -> None:
    """The header's step 3 with tmax = inf weighs the leading term over (0, K], K the bound on
    the positive roots: 1.09e-133 t^2 beside -8.9e96 t makes the root 8.1e229 and is kept (the
    leading term is at least twice each term of the other sign there); 3e-30 t^3 beside 3 t^2,
    whose other roots lie near -1e30, is dropped, and the window becomes (0, K]."""
    c = (-4386.296610043701, -8.87599604097008e96, 1.0897379656641521e-133)
    assert ex.documented_reduction(c, math.inf) == c
    assert ex.judge(c, math.inf, 0, math.nan, False) == "miss"
    assert ex.documented_reduction(c, 1e300) == c
    drop = (-4.5, 3.75, 3.0, 3e-30)
    reduced, window = ex.documented_window(drop, math.inf)
    assert reduced == drop[:3] and 1e10 < window < 1e11
    assert ex.judge(drop, math.inf, 1, 0.75, False) == "ok-root"
    # 1 - 1e-10 t + 2^-14 t^2 has no real root; its rest 1 - 1e-10 t has 1e10, beyond K =
    # 2^-18 (and over (0, K] the t term is negligible in turn)
    spurious = (1.0, -1e-10, 2.0**-14)
    reduced, window = ex.documented_window(spurious, math.inf)
    assert reduced == (1.0,) and window == 2.0**-18
    assert ex.judge(spurious, math.inf, 1, 1e10, False) == "false"
    assert ex.judge(spurious, math.inf, 0, math.nan, False) == "ok-none"
    assert ex.documented_reduction((-2.0, 1.0, 1.0), math.inf) == (-2.0, 1.0, 1.0)
    assert ex.judge((-2.0, 1.0, 1.0), math.inf, 0, math.nan, False) == "miss"

