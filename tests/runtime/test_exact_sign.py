"""exact_sign (issue 33, item 11): inside compensated Horner's rounding band never_late now
asks for p(x)'s exact sign, by Horner in floating-point expansions in C and Rust and in
rationals in Python, each behind the same a priori test (no partial sum of |a_i| x^(i-k) above
2^1000, no term's last bit below 2^-1000). Checked here against exact rational arithmetic on
hypothesis' polynomials, clusters of roots near x above all (where the band is wide), and the
C driver against the Python port's refusals too: the runtimes' answers agree bit for bit only
if both refuse the same inputs."""

from __future__ import annotations

import subprocess
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from max2code_runtime.solver.never_late import _exact_sign
from conftest import require

from .c_program import C_DIR

MAXN = 16


@pytest.fixture(scope="module")
def driver(tmp_path_factory: pytest.TempPathFactory) -> Path:
    gcc = require("gcc")
    out = tmp_path_factory.mktemp("exact_sign") / "exact_sign_driver"
    cmd = [gcc, "-std=c11", "-O2", "-Wall", "-Wextra", "-Werror", "-DM2C_NO_GSL",
           "-I", str(C_DIR), str(Path(__file__).with_name("exact_sign_driver.c")), "-o", str(out),
           "-lm"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 0, f"{' '.join(cmd)}\n{r.stderr}"
    return out


def _exact(a: list[float], x: float) -> int:
    v = Fraction(0)
    for ai in reversed(a):
        v = v * Fraction(x) + Fraction(ai)
    return (v > 0) - (v < 0)


def _times_root(p: list[Fraction], r: Fraction) -> list[Fraction]:
    out = [Fraction(0)] * (len(p) + 1)
    for i, a in enumerate(p):
        out[i + 1] += a
        out[i] -= a * r
    return out


@st.composite
def clusters(draw: st.DrawFn) -> tuple[int, list[float], float]:
    """(n, coefficients rounded once, x): k roots within 1e-12 relative of r (or at r exactly),
    other roots anywhere, a power-of-two scale; x at r or within 1e-9 of it, where
    compensated Horner cannot tell p's sign."""
    degree = draw(st.integers(2, MAXN))
    k = draw(st.integers(2, min(5, degree)))
    r = Fraction(draw(st.floats(0.01, 100)))
    spread = draw(st.sampled_from([0, 1e-15, 1e-12]))
    roots = [r * (1 + Fraction(draw(st.floats(-1, 1))) * Fraction(spread)) for _ in range(k)]
    roots += [Fraction(draw(st.floats(-50, 50))) for _ in range(degree - k)]
    p = [Fraction(draw(st.floats(-8, 8).filter(lambda v: abs(v) > 1e-3)))]
    for root in roots:
        p = _times_root(p, root)
    scale = Fraction(2) ** draw(st.integers(-60, 60))
    a = [float(v * scale) for v in p]
    x = float(r) * (1 + draw(st.sampled_from([0.0, 1e-15, -1e-15, 1e-12, -1e-12, 1e-9, -1e-9])))
    n = draw(st.integers(1, degree))  # the rest a tail, as never_late's dropped terms
    return n, a, x


wild = st.tuples(st.integers(1, MAXN), st.integers(0, MAXN - 1)).filter(
    lambda nm: nm[0] + nm[1] <= MAXN).flatmap(lambda nm: st.tuples(
        st.just(nm[0]),
        st.lists(st.one_of(st.just(0.0), st.floats(-1e300, 1e300, allow_subnormal=True)),
                 min_size=nm[0] + nm[1] + 1, max_size=nm[0] + nm[1] + 1),
        st.floats(5e-324, 2.0**60)))


def _run(driver: Path, cases: list[tuple[int, list[float], float]]) -> list[int]:
    lines = "".join(f"{n} {len(a) - n - 1} {x.hex()} " + " ".join(v.hex() for v in a) + "\n"
                    for n, a, x in cases)
    out = subprocess.run([str(driver)], input=lines, capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    return [int(v) for v in out.stdout.split()]


@pytest.mark.parametrize("kind", ["clusters", "wild"])
def test_exact_sign_is_exact_and_refuses_alike(driver: Path, kind: str) -> None:
    tally = {"decided": 0, "refused": 0}

    @settings(max_examples=5, deadline=None, derandomize=True, database=None,
              suppress_health_check=list(HealthCheck))
    @given(st.lists(clusters() if kind == "clusters" else wild, min_size=40, max_size=40))
    def batch(cases: list[tuple[int, list[float], float]]) -> None:
        for (n, a, x), got in zip(cases, _run(driver, cases)):
            py = _exact_sign(a[:n + 1], n, a[n + 1:], x)
            assert got == py, f"C {got}, Python {py} for n={n} a={a!r} x={x!r}"
            if got == 2:
                tally["refused"] += 1
            else:
                tally["decided"] += 1
                assert got == _exact(a, x), f"{got} for n={n} a={a!r} x={x!r}"
    batch()
    assert tally["decided"] > tally["refused"], tally  # the test mostly lets it run
