"""The pure-Python solver takes the C solver's path, step for step, not only its answers.

The other comparisons (test_fuzz_runtimes, bench/roots.py --only-runtimes) check answers bit
for bit, and answers are robust: a root is polished to the last bit from any bracket, so a
port that skips a whole step of the algorithm still agrees.  (The pure-Python solver without
the C runtime's Bernstein test gave the same answers as C on all 23,901 solves of this test at
M2C_FLOW_COUNT=500, and took a different path on 17,571 of them.)  So here the C runtime is
built with its cost accounting (-DM2C_COUNT, tests/runtime/counts_driver.c) and, for every
solve, the pure-Python solver's counts of the same events must equal C's: Newton steps with
plain and with compensated evaluation, Taylor points, derivative-method calls and Bernstein
tests -- along with the status, the root's bits and the graze flag.  Counts see a last bit
only where it flips a decision, so the Bernstein kernels (coefficients, the guess, the
exclusion by halving, the speculative Laguerre root and its number of steps) are also
compared bit for bit on every Point the solves test (tests/runtime/bernstein_driver.c).

Inputs: the hard cases, random polynomials (degree 2-8), every benchmark family (degrees up to
16, grazes, complex pairs near the window, extreme scales) and the fuzz vectors; each by the
interval method with and without the graze check and with a contact skin.  M2C_FLOW_COUNT sets
the random polynomials and fuzz vectors (and a tenth of it the polynomials per benchmark
family); the default, 300, takes about 15 s.
"""
from __future__ import annotations

import importlib.util
import math
import os
import re
import subprocess
from collections import Counter
from pathlib import Path
from typing import Any, Callable, Sequence

import pytest

from conftest import require

from . import cases, fuzz
from .spy import patch_solver

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


# An octic (0.87 its first root) whose Laguerre guess meets a step to the left (den > 0) at x
# > 0: C gives up there; a port without that exit certified its guess instead (0 Taylor points,
# not 4).  Found by a random search: the inputs below reach den > 0 only where the step then
# leaves (0, T) anyway, so they could not tell the two apart.
LEFT_STEP = ([float.fromhex(h) for h in (
    "0x1.357212d7a38ecp+2", "-0x1.349bc092761d8p+2", "0x1.ddfd431f4c840p+0",
    "-0x1.9f7115da4c66cp+3", "0x1.d3e5ac3389772p+3", "0x1.44bb3eb7b0090p+0",
    "-0x1.3b59ac04469b1p+3", "0x1.63bb50a05bef4p+2", "-0x1.0000000000000p+0")], 10.0)

# Two octics with a complex pair d +- i v close to the axis before their first root (A: d =
# 0.1108, v/d = 4e-5, first root 0.653; B: d = 8.03, v/d = 2e-5, first root 53.0), where p at
# the critical point is 2^10-2^20 times the rounding bound: a touch for the guess (C's
# TOUCH_NEAR = 2^20; with 2^10 both took the Taylor points instead), and the counts go on
# from the right end of the touch's interval: A's window has q's even Bernstein count, whose
# halving C skips after a touch; B's next interval has an odd count, which gets its Bernstein
# test after a touch.  Found by a random search: without them no input here told those apart.
NEAR_TOUCHES = [([float.fromhex(h) for h in hs.split()], float.fromhex(t)) for hs, t in (
    ("0x1.329761bef6c69p-3 -0x1.af2d7d2af1411p+1 0x1.93e31b471e0b5p+4 -0x1.24c08e4b7658ap+6 "
     "0x1.7060f5949df85p+6 -0x1.42f9d59ac890fp+5 -0x1.1cf7e6d5578a7p+3 0x1.d49e76a729195p+2 "
     "0x1.0000000000000p+0", "0x1.14130e9a5b13ep+1"),
    ("-0x1.631f07bd67c70p+27 -0x1.3d32c6a891dbcp+28 -0x1.e56dd6ea35857p+23 0x1.d4e6d8d83bd96p+23 "
     "0x1.a2ecd3018a061p+17 -0x1.b2d35f1504454p+17 0x1.49e934ce2e3d0p+13 -0x1.608a5256a72dap+7 "
     "0x1.0000000000000p+0", "0x1.eb69bb05d7a42p+6"))]


# Step 0b (cleared_at_once) only where the exponents show the leading term far from negligible
# (leading_far): this quartic's -2^-50 t^4 is below 16 eps of its t term over (0, 1], so reduce
# drops it, and the exclusion test at 0 over [0, 1] fails on the quartic (c2 is 14 ulps above
# where it would not) but holds on the cubic.  A port without that guard tested the quartic,
# failed, then skipped the cubic's test at T = 1 as already failed, and ran a Bernstein test
# that C does not; no other input told them apart.
NEGLIGIBLE_LEAD = ([1e-3, 1.0, float.fromhex("0x1.000000000001ep-1"), -0.5, -2.0**-50], 1.0)

# Quintics with a complex pair u +- i d near the axis (d = 1e-12 to 1e-6 u) before a root or the
# window's end: Laguerre's steady step ratios lead the guess to a touch (p within 2^20 rounding
# bounds at the critical point), but the derivative method finds nothing in (lo, hi] around it,
# so the counts go on from hi: a root beyond; none; hi at T (cleared).  Found by a random
# search; the inputs above never reach that part of the touch path.
NEAR_TOUCH = [([float.fromhex(h) for h in cs], float.fromhex(t)) for cs, t in (
    (("-0x1.dca5ce69bcb94p+5", "0x1.364dedd45e600p+7", "-0x1.2f963f6e3e2a7p+7",
      "0x1.1277af52c7a0fp+6", "-0x1.c0f0afbff1f9dp+3", "0x1.0000000000000p+0"),
     "0x1.ee7f2f3be7debp+2"),
    (("0x1.3d04a929476d9p+6", "-0x1.229ad137fca8dp+7", "0x1.85f3e6dae99a0p+5",
      "0x1.bbf41691df447p+4", "-0x1.6b766e17e10fdp+3", "0x1.0000000000000p+0"),
     "0x1.09c5d94f89c05p+0"),
    (("0x1.0ba38c503c6d8p+4", "-0x1.68cc104d55c71p+5", "0x1.2978f048a42b4p+5",
      "-0x1.684ed5b854f7ap+2", "-0x1.0a335029ac271p+2", "0x1.0000000000000p+0"),
     "0x1.e29760228fc46p-1"))]


def _inputs() -> list[Vector]:
    out: list[Vector] = [(c.coeffs, c.tmax) for c in cases.all_cases()] + [LEFT_STEP] + NEAR_TOUCHES
    out.append(NEGLIGIBLE_LEAD)
    out += NEAR_TOUCH
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
        patch_solver(monkeypatch, name, counted)

    wrap("value_and_slope", lambda args: 1 if args[5] else 0)  # once per Newton step
    wrap("point_at", lambda args: 2)
    wrap("derivative_method", lambda args: 3)
    wrap("bernstein_test", lambda args: 4)
    return counts


def _outcomes(solver: Any, monkeypatch: pytest.MonkeyPatch) -> Counter[str]:
    """How the pure-Python solver's speculation and Bernstein exclusion end, over all solves:
    C counts neither (speculate_first_root's Laguerre steps and bernstein_clear's halvings
    only as multiply-adds, which this test does not compare), so the path equality says nothing about them unless the
    inputs reach each of their ends."""
    seen: Counter[str] = Counter()

    def wrap(name: str, outcome: Callable[[Any], str]) -> None:
        inner = getattr(solver, name)

        def observed(*args: Any) -> Any:
            r = inner(*args)
            seen[outcome(r)] += 1
            return r
        patch_solver(monkeypatch, name, observed)

    wrap("speculate_first_root", lambda r: "no guess root" if r.root is None else "guess root")
    wrap("speculate_first_root", lambda r: "touch" if r.touch > 0 else "no touch")
    wrap("bernstein_clear", lambda r: "cleared by halving" if r else "not cleared by halving")
    return seen


def test_pure_python_takes_c_path(counts_driver: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import max2code_runtime as rt
    from max2code_runtime import solver

    monkeypatch.setattr(rt, "_C", None)
    counts = _counting(solver, monkeypatch)
    outcomes = _outcomes(solver, monkeypatch)
    guessed = [False]  # the solve's guess gave a root (its certificate may still fail)
    speculate = solver.speculate_first_root

    def speculating(*args: Any) -> Any:
        r = speculate(*args)
        guessed[0] |= r.root is not None
        return r
    patch_solver(monkeypatch, "speculate_first_root", speculating)
    lines, mine, guesses = [], [], []
    for c, tmax in _inputs():
        for method, number, eps in CALLS:
            lines.append(" ".join([str(number), repr(eps), _num(tmax), str(len(c) - 1),
                                   *(_num(x) for x in c)]))
            counts[:] = [0] * len(EVENTS)
            guessed[0] = False
            st, t, g = rt.first_root_status(list(c), tmax, method, eps)
            mine.append((st, t if st == 1 else 0.0, g if st == 1 else False, tuple(counts)))
            guesses.append(guessed[0])
    r = subprocess.run([str(counts_driver)], input="\n".join(lines) + "\n", capture_output=True,
                       text=True, timeout=600)
    assert r.returncode == 0 and r.stderr == "", r.stderr[-2000:]
    theirs = r.stdout.splitlines()
    assert len(theirs) == len(lines)
    bad, bernstein, certified = [], 0, 0
    for line, text, (st, t, g, ev), guess in zip(lines, theirs, mine, guesses):
        w = text.split()
        cst, ct, cg = int(w[0]), float.fromhex(w[1]), w[2] == "1"
        cev = tuple(int(x) for x in w[3:])
        bernstein += cev[4]
        # a root after a guess, one Bernstein test and no Taylor point nor derivative method:
        # the guess's certificate (on the same path, Python's guess is C's)
        certified += cst == 1 and guess and cev[2:] == (0, 0, 1)
        if (cst, ct.hex(), cg) != (st, t.hex(), g):
            bad.append(f"answer: C {(cst, ct.hex(), cg)} vs Python {(st, t.hex(), g)}: {line}")
        elif cev != ev:
            diff = ", ".join(f"{name} C {a} Python {b}" for name, a, b in zip(EVENTS, cev, ev) if a != b)
            bad.append(f"path: {diff}: {line}")
    assert bernstein > len(lines) // 2, "the inputs hardly reach the Bernstein test"
    assert certified > len(lines) // 20, f"C certified a guessed root in {certified} solves"
    ends = ("guess root", "no guess root", "cleared by halving", "not cleared by halving",
            "touch")
    assert all(outcomes[k] > len(lines) // 100 for k in ends), f"rarely reached: {outcomes}"
    assert not bad, f"{len(bad)} of {len(lines)} solves differ, first:\n" + "\n".join(bad[:10])


def test_failed_first_test_not_repeated(monkeypatch: pytest.MonkeyPatch) -> None:
    """Where step 0b's exclusion test (cleared_at_once) has failed on [0, tmax] and the window
    is still tmax (T = failed_w), isolate_first_root's first test would be the same one on
    the same bits: C skips it and goes on to the guess (max2code_roots.h, step 0).  C
    does not count these tests, and a repeat fails again, so answers and the events compared
    above are the same either way (a port without the skip passed that test): here no
    _bounds_positive call between step 0b and the solve's first Bernstein test may have step
    0b's arguments, bit for bit (the loop's first interval, (0, T] again, may: C tests it
    there too), and the inputs must reach the skip."""
    import max2code_runtime as rt
    from max2code_runtime import solver

    monkeypatch.setattr(rt, "_C", None)
    events: list[tuple[str, tuple[str, ...]]] = []
    in_0b, skips = [False], [0]
    bounds, at_once, isolate, bernstein = (solver.bounds_positive, solver.cleared_at_once,
                                           solver.isolate_first_root, solver.bernstein_test)

    def recorded(qt: Sequence[float], tol: Sequence[float], n: int, w: float, d: int) -> Any:
        events.append(("0b" if in_0b[0] else "test", (
            str(n), _num(w), str(d), *(_num(v) for v in qt[: n + 1]),
            *(_num(v) for v in tol[: n + 1]))))
        return bounds(qt, tol, n, w, d)

    def step_0b(*args: Any) -> Any:
        in_0b[0] = True
        try:
            return at_once(*args)
        finally:
            in_0b[0] = False

    def isolating(*args: Any) -> Any:
        skips[0] += args[3] == args[4]  # T == failed_w
        return isolate(*args)

    def bernstein_test(*args: Any) -> Any:
        events.append(("bernstein", ()))
        return bernstein(*args)
    patch_solver(monkeypatch, "bounds_positive", recorded)
    patch_solver(monkeypatch, "cleared_at_once", step_0b)
    patch_solver(monkeypatch, "isolate_first_root", isolating)
    patch_solver(monkeypatch, "bernstein_test", bernstein_test)
    repeated, solves = [], 0
    for c, tmax in _inputs():
        for method, _, eps in CALLS:
            events.clear()
            rt.first_root_status(list(c), tmax, method, eps)
            solves += 1
            kinds = [kind for kind, _ in events]
            before = events[: kinds.index("bernstein")] if "bernstein" in kinds else events
            first = {key for kind, key in before if kind == "0b"}
            if any(kind == "test" and key in first for kind, key in before):
                repeated.append(f"{method} eps={eps!r} tmax={_num(tmax)} c={[_num(x) for x in c]}")
    assert skips[0] > solves // 100, f"the skip was reached in {skips[0]} of {solves} solves"
    assert not repeated, (f"{len(repeated)} solves repeat step 0b's test, first:\n"
                          + "\n".join(repeated[:5]))


@pytest.fixture(scope="module")
def bernstein_driver(tmp_path_factory: pytest.TempPathFactory) -> Path:
    gcc = require("gcc")
    out = tmp_path_factory.mktemp("bernstein") / "bernstein_driver"
    cmd = [gcc, "-std=c11", "-O2", "-Wall", "-Wextra", "-Werror", "-DM2C_NO_GSL", "-DM2C_COUNT",
           "-I", str(C_DIR), str(Path(__file__).with_name("bernstein_driver.c")), "-o", str(out),
           "-lm"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 0, f"{' '.join(cmd)}\n{r.stderr}"
    return out


def _bernstein_calls(monkeypatch: pytest.MonkeyPatch) -> list[tuple[Any, int, float]]:
    """The Points and widths the pure-Python solver tests over the inputs (with each width
    also times 0.75, off the powers of two): where the kernels run in real solves."""
    import max2code_runtime as rt
    from max2code_runtime import solver

    monkeypatch.setattr(rt, "_C", None)
    calls: list[tuple[Any, int, float]] = []
    inner = solver.bernstein_test

    def recorded(*args: Any) -> Any:
        calls.append((args[0], args[1], args[2]))
        calls.append((args[0], args[1], args[2] * 0.75))
        return inner(*args)
    patch_solver(monkeypatch, "bernstein_test", recorded)
    for c, tmax in _inputs():
        for method, _, eps in CALLS:
            rt.first_root_status(list(c), tmax, method, eps)
    patch_solver(monkeypatch, "bernstein_test", inner)
    return calls


def _kernel_line(solver: Any, pt: Any, n: int, w: float, seen: Counter[str],
                 steps: list[int]) -> list[str]:
    """What bernstein_driver.c prints for the Point, computed by the pure-Python kernels; seen
    counts the ends reached, steps[0] the Laguerre and Newton-on-p' steps (solver.laguerre_terms
    calls), steps[1] the rounding bounds at a critical point (solver.horner_abs calls)."""
    first = solver.bernstein_test(pt, n, w, True)
    out = [str(first.answer), _num(first.pend)]
    seen[f"answer {first.answer}"] += 1
    if first.q is not None:
        cleared = solver.bernstein_clear(first.q, n, 0.0)
        cleared_at = solver.bernstein_clear(first.q, n, 0.3)
        seen["cleared by halving" if cleared else "not cleared by halving"] += 1
        seen["cleared, split at 0.3" if cleared_at else "not cleared, split at 0.3"] += 1
        out += [_num(v) for v in first.q.b]
        out += [_num(first.q.err), str(int(first.q.even)), str(int(cleared)), str(int(cleared_at))]
    steps[:] = [0, 0]
    r, touch, dip, over = solver.speculate_first_root(pt.pt, n, pt.x + w)
    seen["no guess root" if r is None else "guess root"] += 1
    seen["touch" if touch > 0 else "no touch"] += 1
    seen["dip" if dip != 0 else "no dip"] += 1
    seen["overshot" if over > 0 else "not overshot"] += 1
    seen[f"{steps[0]} Laguerre steps"] += 1
    # (C's OVERSHOT is 2, with Newton's start in r and the step's end in over)
    out += ["0", _num(0.0)] if r is None else ["2" if over > 0 else "1", _num(r)]
    out += [_num(touch), _num(dip), _num(over)]
    out.append(str(3 * n * steps[0] + n * steps[1]))  # C's count: 3 n a step, n a bound
    second = solver.bernstein_test(pt, n, w, False)
    return out + [str(second.answer), _num(second.pend)]


def _c_token(text: str) -> str:
    """A token of bernstein_driver.c's output as _kernel_line writes it (%a read back)."""
    if "x" in text or "nan" in text or "inf" in text:
        return _num(float.fromhex(text))
    return text


def test_bernstein_kernels_bit_for_bit(bernstein_driver: Path,
                                       monkeypatch: pytest.MonkeyPatch) -> None:
    """bernstein_test's coefficients and p(x + w), bernstein_clear's verdict on q's
    coefficients and speculate_first_root's root and number of steps: the pure-Python kernels
    give C's bits on every Point the solves test.  The counts above see a last bit only where it flips a
    decision (a port summing the Bernstein coefficients in the old order passed them at
    M2C_FLOW_COUNT=1000); here every bit is compared."""
    from max2code_runtime import solver

    calls = _bernstein_calls(monkeypatch)
    steps = [0, 0]
    terms, bound = solver.laguerre_terms, solver.horner_abs

    def counted(*args: Any) -> Any:
        steps[0] += 1
        return terms(*args)

    def bounded(*args: Any) -> Any:
        steps[1] += 1
        return bound(*args)
    patch_solver(monkeypatch, "laguerre_terms", counted)
    patch_solver(monkeypatch, "horner_abs", bounded)
    lines, mine = [], []
    seen: Counter[str] = Counter()
    for pt, n, w in calls:
        lines.append(" ".join([str(n), _num(pt.x), _num(w), *(_num(v) for v in pt.pt),
                               *(_num(v) for v in pt.qt), *(_num(v) for v in pt.tol)]))
        mine.append(_kernel_line(solver, pt, n, w, seen, steps))
    r = subprocess.run([str(bernstein_driver)], input="\n".join(lines) + "\n",
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0 and r.stderr == "", r.stderr[-2000:]
    theirs = [[_c_token(t) for t in text.split()] for text in r.stdout.splitlines()]
    assert len(theirs) == len(lines)
    bad = [f"C {c}\nPython {p}\ninput {line}" for line, c, p in zip(lines, theirs, mine) if c != p]
    assert not bad, f"{len(bad)} of {len(lines)} differ, first:\n" + "\n".join(bad[:5])
    ends = [f"answer {a}" for a in (solver.BERN_UNKNOWN, solver.BERN_CLEAR, solver.BERN_ONE)]
    ends += ["cleared by halving", "not cleared by halving", "cleared, split at 0.3",
             "not cleared, split at 0.3", "guess root", "no guess root", "touch", "dip", "overshot"]
    assert all(seen[k] > len(lines) // 100 for k in ends), f"rarely reached: {seen}"


def _c_table(name: str) -> list[list[float]]:
    """A static double[][] initialiser of the C runtime, its entries (integers and `1.0 / N`)
    evaluated as C's constant expressions round: the integer converted exactly, one division."""
    src = "".join(path.read_text() for path in [C_DIR / "max2code_roots.c",
                                                *sorted(C_DIR.glob("roots/*.inc"))])
    found = re.search(rf"\b{name}\[MAXN \+ 1\]\[MAXN \+ 1\] = \{{", src)
    assert found is not None, f"{name} not found in the C runtime's sources"
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
