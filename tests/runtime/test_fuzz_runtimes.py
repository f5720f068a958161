"""Every runtime at the extremes (issue 12): adversarial vectors through C, Modula-2, Rust and
Python, and the C runtime once under -fsanitize=address,undefined.

For every vector (tests/runtime/fuzz.py: NaN, +-Inf, subnormals, +-1e308, 1e-200/1e200
mixtures, (t - a)^k, tmax 0 / negative / NaN / inf / tiny) and every method:

* no crash, no sanitizer report, no call over 1 ms of CPU time (C and Rust time each call
  themselves; a call over the limit is timed again three times and only fails if it stays
  over: the machine is shared);
* status -1 exactly on invalid input, status 1 only with a finite t in (0, tmax];
* the same answer from C, Modula-2 (the C runtime through its binding), Rust and Python
  bit for bit: they run one algorithm (the Rust runtime is a port of the C one, Python calls
  C through cffi or runs its port of it).

FUZZ_COUNT vectors per run (10^4 by default, as in CI); FUZZ_COUNT=1000000 runs 10^6 in
batches of FUZZ_BATCH (10^5).  The four C methods, and the default with a contact skin, are
each run on every vector.
"""
from __future__ import annotations

import math
import os
import subprocess
from pathlib import Path
from typing import Sequence

import mpmath
import pytest

from conftest import require

from . import cases, fuzz

ROOT = Path(__file__).resolve().parents[2]
C_DIR = ROOT / "runtime" / "c"
COUNT = int(os.environ.get("FUZZ_COUNT", "10000"))
BATCH = int(os.environ.get("FUZZ_BATCH", "100000"))
LIMIT_NS = 1_000_000  # 1 ms
SKIN = 1e-9

Answer = tuple[int, float, bool]


def _num(x: float) -> str:
    return float(x).hex() if math.isfinite(x) else repr(float(x))


def c_line(method: int | str, c: Sequence[float], tmax: float) -> str:
    return " ".join([str(method), _num(tmax), str(len(c) - 1), *(_num(x) for x in c)])


def c_lines(vecs: Sequence[fuzz.Vector]) -> list[str]:
    """Per vector: methods 0..3, then the default with the contact skin."""
    return [c_line(m, c, t) for c, t in vecs for m in (0, 1, 2, 3, f"0:{SKIN!r}")]


def build_driver(out: Path, sanitize: bool = False) -> Path:
    gcc = require("gcc")
    flags = ["-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic"]
    if sanitize:
        flags += ["-O1", "-g", "-fsanitize=address,undefined", "-fno-sanitize-recover=all",
                  "-fno-omit-frame-pointer"]
    else:
        flags += ["-O2"]
    cmd = [gcc, *flags, "-I", str(C_DIR), str(C_DIR / "max2code_roots.c"),
           str(C_DIR / "max2code_roots_driver.c"), "-o", str(out), "-lgsl", "-lgslcblas", "-lm"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 0, f"{' '.join(cmd)}\n{r.stderr}"
    return out


def run_timed(exe: Path, lines: Sequence[str], env: dict[str, str] | None = None
              ) -> list[tuple[int, float, bool, float]]:
    r = subprocess.run([str(exe), "--time"], input="\n".join(lines) + "\n", capture_output=True,
                       text=True, timeout=900, env=env)
    assert r.returncode == 0 and r.stderr == "", f"exit {r.returncode}:\n{r.stderr[-4000:]}"
    out = []
    for text in r.stdout.splitlines():
        st, t, g, ns = text.split()
        out.append((int(st), float(t), g == "1", float(ns)))
    assert len(out) == len(lines)
    return out


def slow_calls(exe: Path, lines: Sequence[str], answers: Sequence[tuple[int, float, bool, float]]
               ) -> list[str]:
    """Lines whose call took over LIMIT_NS, and still does at best of three."""
    slow = [ln for ln, a in zip(lines, answers) if a[3] > LIMIT_NS]
    if not slow:
        return []
    again = [run_timed(exe, slow) for _ in range(3)]
    return [ln for i, ln in enumerate(slow) if min(a[i][3] for a in again) > LIMIT_NS]


def contract_failures(vecs: Sequence[fuzz.Vector], answers: Sequence[Answer | tuple], per: int
                      ) -> list[str]:
    bad = []
    for i, (c, tmax) in enumerate(vecs):
        for j in range(per):
            st, t = answers[i * per + j][:2]
            why = fuzz.check_answer(c, tmax, st, t)
            if why:
                bad.append(f"{why}: method #{j}, c={c!r}, tmax={tmax!r}")
    return bad


@pytest.fixture(scope="module")
def driver(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return build_driver(tmp_path_factory.mktemp("fuzz") / "roots_driver")


@pytest.fixture(scope="module")
def c_answers(driver: Path) -> list[tuple[list[fuzz.Vector], list[str], list]]:
    out = []
    for vecs in fuzz.batches(COUNT, BATCH):
        lines = c_lines(vecs)
        out.append((vecs, lines, run_timed(driver, lines)))
    return out


def test_issue12_reproducers(driver: Path) -> None:
    """The probe's own vectors.  The first gave t = 0 (its root near -1e-400 underflowed):
    now the variable is rescaled and the real first root, (1e200 / 1e100)^(1/3), comes out;
    the second's root overflows (status 0, not t = inf); the subnormal UBSan case and the
    GSL hang return."""
    sub = float.fromhex
    lines = [
        c_line(0, (1e-200, 1e200, -0.5, 1e-200, -1e100), math.inf),
        c_line(0, (-1.7976931348623157e308, 5e-324), math.inf),
        c_line(0, (sub("0x1.a33532f76beb7p+823"), 0.5, sub("0x0.fffffffffffffp-1022"),
                   -sub("0x0.0000000000001p-1022")), math.inf),
        *(c_line(m, (sub("0x0.730d67819e8d2p-1022"), sub("0x1.0c5c438e85eb4p+2"),
                     sub("0x0.fffffffffffffp-1022"), -sub("0x1p-1022"), -0.0), math.inf)
          for m in range(4)),
    ]
    res = run_timed(driver, lines)
    # -1e100 t^4 + 1e200 t dominate near the root (the rest is 1e-167 relative there)
    with mpmath.workdps(60):
        root = mpmath.cbrt(mpmath.mpf(1e200) / mpmath.mpf(1e100))
    assert res[0][0] == 1 and cases.rel_error(res[0][1], root) < 4e-16
    assert res[1][0] == 0
    for st, t, _, ns in res:
        assert st in (0, 1) and (st == 0 or 0 < t < math.inf) and ns < LIMIT_NS


def test_c_contract(c_answers) -> None:
    bad = [b for vecs, _, ans in c_answers for b in contract_failures(vecs, ans, 5)]
    assert not bad, f"{len(bad)} failures, first:\n" + "\n".join(bad[:10])


def test_c_no_call_over_1ms(driver: Path, c_answers) -> None:
    slow = [s for _, lines, ans in c_answers for s in slow_calls(driver, lines, ans)]
    assert not slow, f"{len(slow)} calls over 1 ms, first:\n" + "\n".join(slow[:10])


def test_c_under_sanitizers(tmp_path: Path) -> None:
    """The hard cases, random polynomials and a fuzz batch under ASan + UBSan: any report
    aborts the driver (-fno-sanitize-recover), so exit 0 with empty stderr means none."""
    exe = build_driver(tmp_path / "roots_driver_san", sanitize=True)
    lines = [c_line(m, case.coeffs, case.tmax) for case in cases.all_cases() for m in range(4)]
    lines += [c_line(m, rc.coeffs, rc.tmax) for rc in cases.random_cases(300) for m in range(4)]
    lines += c_lines(fuzz.vectors(min(COUNT, 10000), seed=99))
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=1:abort_on_error=0",
               UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1")
    res = run_timed(exe, lines, env=env)
    assert all(st in (-1, 0, 1) for st, *_ in res)
