"""The pure-Python solver takes the C solver's path, step for step, not only its answers.

The other comparisons (test_fuzz_runtimes, bench/roots.py --only-runtimes) check answers bit
for bit, and answers are robust: a root is polished to the last bit from any bracket, so a
port that skips a whole step of the algorithm still agrees.  (The pure-Python solver without
the C runtime's Bernstein test gave the same answers as C on all 23,901 solves of this test at
M2C_FLOW_COUNT=500, and took a different path on 17,571 of them.)  So here the C runtime is
built with its cost accounting (-DM2C_COUNT, tests/runtime/counts_driver.c) and, for every
solve, the pure-Python solver's counts of the same events must equal C's: Newton steps with
plain and with compensated evaluation, Taylor points, derivative-method calls and Bernstein
tests -- along with the status, the root's bits and the graze flag.

Inputs: the hard cases, random polynomials (degree 2-8), every benchmark family (degrees up to
16, grazes, complex pairs near the window, extreme scales) and the fuzz vectors; each by the
interval method with and without the graze check and with a contact skin.  M2C_FLOW_COUNT sets
the random polynomials and fuzz vectors (and a tenth of it the polynomials per benchmark
family); the default, 300, takes about 10 s.
"""
from __future__ import annotations

import importlib.util
import math
import os
import re
import subprocess
from pathlib import Path
from typing import Any, Callable, Sequence

import pytest

from conftest import require

from . import cases, fuzz

ROOT = Path(__file__).resolve().parents[2]
C_DIR = ROOT / "runtime" / "c"
COUNT = int(os.environ.get("M2C_FLOW_COUNT", "300"))
# (method name for Python, C method number, contact skin)
CALLS = (("interval", 0, 0.0), ("interval-nograze", 1, 0.0), ("interval", 0, 1e-9))
# m2c_count's indices in the order counts_driver.c prints them
EVENTS = ("plain Newton steps", "compensated Newton steps", "Taylor points",
          "derivative-method calls", "Bernstein tests")

Vector = tuple[Sequence[float], float]


def _bench_polynomials(per_family: int) -> list[Vector]:
    spec = importlib.util.spec_from_file_location("bench_roots", ROOT / "bench" / "roots.py")
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return [(c, t) for _, c, t in mod.polynomials(per_family)]


def _inputs() -> list[Vector]:
    out: list[Vector] = [(c.coeffs, c.tmax) for c in cases.all_cases()]
    out += [(c.coeffs, c.tmax) for c in cases.random_cases(COUNT)]
    out += _bench_polynomials(max(1, COUNT // 10))
    out += fuzz.vectors(COUNT, seed=7)
    return out


def _num(x: float) -> str:
    return float(x).hex() if math.isfinite(x) else repr(float(x))


@pytest.fixture(scope="module")
def counts_driver(tmp_path_factory: pytest.TempPathFactory) -> Path:
    gcc = require("gcc")
    out = tmp_path_factory.mktemp("flow") / "counts_driver"
    cmd = [gcc, "-std=c11", "-O2", "-Wall", "-Wextra", "-Werror", "-DM2C_COUNT", "-I", str(C_DIR),
           str(C_DIR / "max2code_roots.c"), str(Path(__file__).with_name("counts_driver.c")),
           "-o", str(out), "-lgsl", "-lgslcblas", "-lm"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 0, f"{' '.join(cmd)}\n{r.stderr}"
    return out


def _counting(solver: Any, monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Wraps the solver's functions where C counts an event; returns the live counters."""
    counts = [0] * len(EVENTS)

    def wrap(name: str, which: Callable[[tuple], int]) -> None:
        inner = getattr(solver, name)

        def counted(*args: Any) -> Any:
            counts[which(args)] += 1
            return inner(*args)
        monkeypatch.setattr(solver, name, counted)

    wrap("_value_and_slope", lambda args: 1 if args[5] else 0)  # once per Newton step
    wrap("_point_at", lambda args: 2)
    wrap("_derivative_method", lambda args: 3)
    wrap("_bernstein_test", lambda args: 4)
    return counts


def test_pure_python_takes_c_path(counts_driver: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import max2code_runtime as rt
    from max2code_runtime import solver

    monkeypatch.setattr(rt, "_C", None)
    counts = _counting(solver, monkeypatch)
    lines, mine = [], []
    for c, tmax in _inputs():
        for method, number, eps in CALLS:
            lines.append(" ".join([str(number), repr(eps), _num(tmax), str(len(c) - 1),
                                   *(_num(x) for x in c)]))
            counts[:] = [0] * len(EVENTS)
            st, t, g = rt.first_root_status(list(c), tmax, method, eps)
            mine.append((st, t if st == 1 else 0.0, g if st == 1 else False, tuple(counts)))
    r = subprocess.run([str(counts_driver)], input="\n".join(lines) + "\n", capture_output=True,
                       text=True, timeout=600)
    assert r.returncode == 0 and r.stderr == "", r.stderr[-2000:]
    theirs = r.stdout.splitlines()
    assert len(theirs) == len(lines)
    bad, bernstein = [], 0
    for line, text, (st, t, g, ev) in zip(lines, theirs, mine):
        w = text.split()
        cst, ct, cg = int(w[0]), float.fromhex(w[1]), w[2] == "1"
        cev = tuple(int(x) for x in w[3:])
        bernstein += cev[4]
        if (cst, ct.hex(), cg) != (st, t.hex(), g):
            bad.append(f"answer: C {(cst, ct.hex(), cg)} vs Python {(st, t.hex(), g)}: {line}")
        elif cev != ev:
            diff = ", ".join(f"{name} C {a} Python {b}" for name, a, b in zip(EVENTS, cev, ev) if a != b)
            bad.append(f"path: {diff}: {line}")
    assert bernstein > len(lines) // 2, "the inputs hardly reach the Bernstein test"
    assert not bad, f"{len(bad)} of {len(lines)} solves differ, first:\n" + "\n".join(bad[:10])


def _c_table(name: str) -> list[list[float]]:
    """A static double[][] initialiser of the C runtime, its entries (integers and `1.0 / N`)
    evaluated as C's constant expressions round: the integer converted exactly, one division."""
    src = (C_DIR / "max2code_roots.c").read_text()
    found = re.search(rf"\b{name}\[MAXN \+ 1\]\[MAXN \+ 1\] = \{{", src)
    assert found is not None, f"{name} not found in max2code_roots.c"
    body = src[found.end():src.index("};", found.end())]
    rows = []
    for row in re.findall(r"\{([^{}]*)\}", body):
        vals = []
        for item in (x.strip() for x in row.split(",") if x.strip()):
            m = re.fullmatch(r"1\.0 / (\d+)", item)
            vals.append(1.0 / int(m.group(1)) if m else float(int(item)))
        rows.append(vals)
    return rows


def test_binomial_tables_are_c_ones() -> None:
    """The Python tables, entry for entry, are the C source's (a typo there is C's answer)."""
    from max2code_runtime import solver

    inv = _c_table("INV_BINOM")
    assert len(inv) == solver.MAXN + 1
    for n, row in enumerate(inv):
        assert [x.hex() for x in row] == [x.hex() for x in solver.INV_BINOM[n]], n
    binom = _c_table("BINOM")
    assert [[x.hex() for x in r] for r in binom] == [[x.hex() for x in r] for r in solver.BINOM]
