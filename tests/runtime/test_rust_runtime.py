"""The Rust runtime (runtime/rust) against the shared hard cases and the mpmath oracle.

The crate's own unit tests run through ``cargo test``; the cross-checks here go through
its ``roots_cli`` example, which reads ``METHOD TMAX c0 c1 ... cn`` lines on stdin and
prints ``root T GRAZE`` (T with 17 significant digits), ``noroot`` or ``invalid``.
Numbers cross as Python ``repr`` (shortest round-trip form), so they arrive exactly.

Needs cargo: under CI (``CI`` set) a missing cargo fails; elsewhere the tests skip.
Build output goes to runtime/rust/target (gitignored).

Run ``python tests/runtime/test_rust_runtime.py`` for the table of worst relative
errors per family and method.
"""
from __future__ import annotations

import math
import os
import shutil
import subprocess
import sys
from collections import defaultdict
from pathlib import Path
from typing import Sequence

import pytest

try:
    from .cases import U, Case, all_cases, oracle, random_cases, rel_error
except ImportError:  # run as a script
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
    from runtime.cases import U, Case, all_cases, oracle, random_cases, rel_error  # type: ignore

ROOT = Path(__file__).resolve().parents[2]
CRATE = ROOT / "runtime" / "rust"
TARGET = CRATE / "target"
CLI_NAME = {"interval": "interval", "interval-nograze": "nograze", "closed": "closed"}
METHODS = tuple(CLI_NAME)  # the Rust runtime has no "gsl" method
GRAZING = ("interval", "closed")
# Random polynomials checked (the 60-digit oracle dominates the run time: ~15 ms each).
RANDOM_COUNT = int(os.environ.get("M2C_RANDOM_COUNT", "1500"))


def gamma(k: int) -> float:
    return k * U / (1 - k * U)


# ---------------------------------------------------------------------------
# Building and running the driver
# ---------------------------------------------------------------------------


def find_cargo() -> str | None:
    path = shutil.which("cargo")
    if path is None:
        home = Path.home() / ".cargo" / "bin" / "cargo"
        path = str(home) if home.exists() else None
    return path


def require_cargo() -> str:
    path = find_cargo()
    if path is None:
        message = "'cargo' is not installed (install Rust via rustup to test runtime/rust)"
        if os.environ.get("CI"):
            pytest.fail(message + " -- required in CI")
        pytest.skip(message)
    return path


def cargo_env() -> dict[str, str]:
    env = dict(os.environ)
    env["CARGO_TARGET_DIR"] = str(TARGET)
    env.setdefault("CARGO_TERM_COLOR", "never")
    return env


def build_cli(cargo: str, example: str = "roots_cli", features: Sequence[str] = ()) -> Path:
    """Builds an example of the crate (release) and returns its path."""
    feat = ["--features", ",".join(features)] if features else []
    proc = subprocess.run(
        [cargo, "build", "--quiet", "--release", "--example", example, *feat],
        cwd=CRATE, env=cargo_env(), capture_output=True, text=True, timeout=600,
    )
    assert proc.returncode == 0, f"cargo build failed:\n{proc.stdout}\n{proc.stderr}"
    exe = TARGET / "release" / "examples" / (f"{example}.exe" if os.name == "nt" else example)
    assert exe.exists(), exe
    return exe


def fmt(x: float) -> str:
    return repr(float(x))  # 'inf', 'nan', '-inf' parse in Rust too


def run_cli(exe: Path, queries: Sequence[tuple[str, float, Sequence[float]]]) -> list[tuple]:
    """Run (method, tmax, coeffs) queries; returns (status, t, graze) per query."""
    text = "".join(
        f"{CLI_NAME[m]} {fmt(tmax)} {' '.join(fmt(x) for x in c)}\n" for m, tmax, c in queries
    )
    proc = subprocess.run([str(exe)], input=text, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert len(lines) == len(queries), (len(lines), len(queries))
    out = []
    for line in lines:
        parts = line.split()
        if parts[0] == "root":
            out.append(("root", float(parts[1]), parts[2] == "1"))
        elif parts[0] in ("noroot", "invalid"):
            out.append((parts[0], None, False))
        else:
            raise AssertionError(f"driver: {line}")
    return out


@pytest.fixture(scope="module")
def cli() -> Path:
    return build_cli(require_cargo())


# ---------------------------------------------------------------------------
# Checking one answer against the oracle
# ---------------------------------------------------------------------------


def graze_target(case: Case):
    """Where a grazing solver should report the first event of a graze case: the
    first near-real complex pair (touch) or the first real root, whichever is first;
    and whether that event is a touch (then the graze flag is required)."""
    o = oracle(case.coeffs, case.tmax)
    cands = [(t, True) for t in o.touches]
    if o.root is not None:
        cands.append((o.root, False))
    return min(cands, key=lambda v: v[0]) if cands else (None, False)


def check(case: Case, method: str, answer: tuple) -> float | None:
    """Assert the answer for one case and method; return its relative error (if any)."""
    status, t, graze = answer
    if case.expect == "invalid":
        assert status == "invalid", (case.name, method, answer)
        return None
    assert status != "invalid", (case.name, method, answer)
    o = oracle(case.coeffs, case.tmax)
    if case.expect == "none":
        if status == "root" and method in GRAZING and o.touches:
            # a near-real complex pair in the window: reporting it as a graze is allowed
            err = min(rel_error(t, z) for z in o.touches)
            assert graze and err <= 1e-6, (case.name, method, answer, o.touches)
            return None
        assert status == "noroot", (case.name, method, answer, o)
        return None
    bound = case.bounds.get(method)
    if case.expect == "graze":
        target, touch = graze_target(case)
        assert target is not None, case.name
        if method not in GRAZING:
            # a no-graze solver may skip the touch; whatever it reports must be a root
            if status == "root" and o.root is not None:
                return None
            return None
        assert status == "root", (case.name, method, answer)
        err = rel_error(t, target)
        if touch:
            assert graze, (case.name, method, answer, "graze flag expected at a touch")
        if bound is not None:
            assert err <= bound, (case.name, method, t, float(target), err, bound)
        return err
    # expect == "root"
    assert o.root is not None
    if bound is None:
        return rel_error(t, o.root) if status == "root" else None
    assert status == "root", (case.name, method, answer, float(o.root))
    err = rel_error(t, o.root)
    bound = max(bound, conditioning_floor(case.coeffs, o.kappa))
    assert err <= bound, (case.name, method, t, float(o.root), err, bound, o.kappa)
    return err


def conditioning_floor(coeffs: Sequence[float], kappa: float) -> float:
    """The accuracy no double-precision evaluation can beat: Horner's error bound
    gamma_{2n} sum|c_i| r^i moves a simple root by up to gamma_{2n} kappa (relative).
    A stated bound below this floor (clustered roots, kappa ~ 1e10) cannot be met by
    any of the runtimes, so the larger of the two is asserted; the report lists them."""
    n = len(coeffs) - 1
    return 2 * gamma(2 * n) * kappa


CASES = all_cases()


@pytest.fixture(scope="module")
def case_answers(cli: Path) -> dict[tuple[str, str], tuple]:
    queries = [(m, c.tmax, c.coeffs) for c in CASES for m in METHODS]
    answers = run_cli(cli, queries)
    return {(c.name, q[0]): a for c, q, a in zip((c for c in CASES for _ in METHODS), queries, answers)}


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_hard_case(case: Case, case_answers) -> None:
    for method in METHODS:
        check(case, method, case_answers[(case.name, method)])


# ---------------------------------------------------------------------------
# Random polynomials: bound from the condition number of the first root
# ---------------------------------------------------------------------------


def random_bound(coeffs: Sequence[float], kappa: float) -> float:
    """A few ulps above the conditioning floor."""
    return 4 * U + conditioning_floor(coeffs, kappa)


def random_check(rc, method: str, answer: tuple) -> float | None:
    status, t, graze = answer
    o = oracle(rc.coeffs, rc.tmax)
    assert status != "invalid", (rc, method, answer)
    if o.root is None:
        if status == "root":
            # only a graze at a near-real pair is acceptable
            assert method in GRAZING and graze and o.touches, (rc, method, answer)
        return None
    if o.kind != "simple" or any(z < o.root for z in o.touches):
        return None  # an (almost) double root comes first: not a conditioning test
    bound = random_bound(rc.coeffs, o.kappa)
    if status != "root":
        # a root within rounding of tmax may legitimately fall outside
        assert not math.isinf(rc.tmax) and rel_error(rc.tmax, o.root) <= bound, (rc, method, answer, o)
        return None
    err = rel_error(t, o.root)
    assert err <= bound, (rc, method, t, float(o.root), err, bound, o.kappa)
    return err


RANDOM = random_cases(RANDOM_COUNT)


def test_random_polynomials(cli: Path) -> None:
    queries = [(m, rc.tmax, rc.coeffs) for rc in RANDOM for m in METHODS]
    answers = run_cli(cli, queries)
    failures = []
    for (m, _, _), rc, a in zip(queries, (rc for rc in RANDOM for _ in METHODS), answers):
        try:
            random_check(rc, m, a)
        except AssertionError as e:  # collect, so one run shows them all
            failures.append(str(e))
    assert not failures, f"{len(failures)} failures, first: {failures[:5]}"


def test_methods_agree_on_random(cli: Path) -> None:
    """Interval and closed agree on every random cubic and quartic with a simple,
    well-conditioned first root."""
    subset = [rc for rc in RANDOM if len(rc.coeffs) in (4, 5)]
    queries = [(m, rc.tmax, rc.coeffs) for rc in subset for m in ("interval", "closed")]
    answers = run_cli(cli, queries)
    for i, rc in enumerate(subset):
        a, b = answers[2 * i], answers[2 * i + 1]
        o = oracle(rc.coeffs, rc.tmax)
        if o.root is None or o.kind != "simple" or o.touches:
            continue
        bound = 2 * random_bound(rc.coeffs, o.kappa)
        assert a[0] == b[0] == "root", (rc, a, b)
        assert abs(a[1] - b[1]) <= bound * abs(a[1]), (rc, a, b, bound)


# ---------------------------------------------------------------------------
# The crate's own tests
# ---------------------------------------------------------------------------


def test_cargo_unit_tests() -> None:
    cargo = require_cargo()
    proc = subprocess.run(
        [cargo, "test", "--quiet"], cwd=CRATE, env=cargo_env(),
        capture_output=True, text=True, timeout=900,
    )
    assert proc.returncode == 0, f"cargo test failed:\n{proc.stdout[-4000:]}\n{proc.stderr[-4000:]}"


# ---------------------------------------------------------------------------
# Report: worst relative error per family and method
# ---------------------------------------------------------------------------


def worst_errors(exe: Path) -> dict[tuple[str, str], tuple[float, str]]:
    worst: dict[tuple[str, str], tuple[float, str]] = defaultdict(lambda: (0.0, ""))
    queries = [(m, c.tmax, c.coeffs) for c in CASES for m in METHODS]
    for (m, _, _), c, a in zip(queries, (c for c in CASES for _ in METHODS), run_cli(exe, queries)):
        try:
            err = check(c, m, a)
        except AssertionError:
            err = math.inf
        if err is not None and err >= worst[(c.family, m)][0]:
            worst[(c.family, m)] = (err, c.name)
    queries = [(m, rc.tmax, rc.coeffs) for rc in RANDOM for m in METHODS]
    for (m, _, _), rc, a in zip(queries, (rc for rc in RANDOM for _ in METHODS), run_cli(exe, queries)):
        try:
            err = random_check(rc, m, a)
        except AssertionError:
            err = math.inf
        if err is not None and err >= worst[("random", m)][0]:
            worst[("random", m)] = (err, f"{rc.coeffs} tmax={rc.tmax}")
    return dict(worst)


def print_report(worst: dict) -> None:
    """One line per family and method: worst relative error, in ulps, and which case."""
    for (family, method), (err, where) in sorted(worst.items()):
        print(f"{family:<12} {method:<17} {err:9.2e} {err / U:12.1f}u  {where[:90]}")


if __name__ == "__main__":
    cargo = find_cargo()
    if cargo is None:
        sys.exit("cargo not found")
    print_report(worst_errors(build_cli(cargo)))
