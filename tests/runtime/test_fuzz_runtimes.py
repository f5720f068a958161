"""Every runtime at the extremes (issue 12): adversarial vectors through C, Modula-2, Rust and
Python, and the C runtime once under -fsanitize=address,undefined.

For every vector (tests/runtime/fuzz.py: NaN, +-Inf, subnormals, +-1e308, 1e-200/1e200
mixtures, (t - a)^k, tmax 0 / negative / NaN / inf / tiny) and every method:

* no crash, no sanitizer report, no call over 1 ms (C, the Rust runtime and Python's C backend
  time each call; a call over the limit is timed again three times and fails only if it
  stays over: the machine is shared).  The pure-Python fallback is 100-300 times slower than C
  by nature; for it the same check is a hang detector at 50 ms;
* status -1 exactly on invalid input, status 1 only with a finite t in (0, tmax];
* the same answer from C, Modula-2 (the C runtime through its binding), Rust and Python (both
  backends), bit for bit, for the interval methods with and without the graze check and with
  a contact skin: they run one algorithm (the Rust and pure-Python runtimes are ports of the C
  one).  The closed-form method ("closed") is each language's own (TOMS 1010 in C and Python,
  Cardano/Ferrari in Rust): for it only the contract above is checked.

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
from . import test_m2_runtime as m2
from . import test_rust_runtime as rust

ROOT = Path(__file__).resolve().parents[2]
C_DIR = ROOT / "runtime" / "c"
COUNT = int(os.environ.get("FUZZ_COUNT", "10000"))
BATCH = int(os.environ.get("FUZZ_BATCH", "100000"))
LIMIT_NS = 1_000_000  # 1 ms
SKIN = 1e-9
M2_CHUNK = 40000  # lines per Modula-2 driver run (run_m2 allows it 120 s)

Answer = tuple[int, float, bool]


def _num(x: float) -> str:
    return float(x).hex() if math.isfinite(x) else repr(float(x))


def c_line(method: int | str, c: Sequence[float], tmax: float) -> str:
    return " ".join([str(method), _num(tmax), str(len(c) - 1), *(_num(x) for x in c)])


def c_lines(vecs: Sequence[fuzz.Vector]) -> list[str]:
    """Per vector: methods 0..3, then the default with the contact skin."""
    return [c_line(m, c, t) for c, t in vecs for m in (0, 1, 2, 3, f"0:{SKIN!r}")]


def build_driver(out: Path, sanitize: bool = False, extra: Sequence[str] = (),
                 cc: str = "gcc") -> Path:
    """The line driver on the C runtime (C11, warnings as errors); `extra` flags come last (a
    -std there wins), `cc` is the compiler (tests/runtime/test_build_variants.py)."""
    gcc = require(cc)
    flags = ["-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic"]
    if sanitize:
        flags += ["-O1", "-g", "-fsanitize=address,undefined", "-fno-sanitize-recover=all",
                  "-fno-omit-frame-pointer"]
    else:
        flags += ["-O2"]
    cmd = [gcc, *flags, *extra, "-I", str(C_DIR), str(C_DIR / "max2code_roots.c"),
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


# ---------------------------------------------------------------------------
# The other runtimes against C
# ---------------------------------------------------------------------------

CROSS = (0, 1, 4)  # positions in c_lines: interval, interval-nograze, interval with the skin


def _same(c_answer: tuple, other: tuple) -> bool:
    """(status, t, graze) equal, t compared bit for bit (NaN == NaN when there is no root)."""
    st, t, g = c_answer[:3]
    ost, ot, og = other[:3]
    if st != ost:
        return False
    return st != 1 or (t == ot and g == og)


def test_rust_same_answers_as_c(c_answers) -> None:
    exe = rust.build_cli(rust.require_cargo())
    names = ("interval", "nograze", "closed", None, f"skin:{SKIN!r}")
    bad, slow = [], []
    for vecs, lines, ans in c_answers:
        queries = [f"{names[j]} {rust.fmt(t)} {' '.join(rust.fmt(x) for x in c)}".rstrip()
                   for c, t in vecs for j in (0, 1, 2, 4)]
        r = subprocess.run([str(exe), "--time"], input="\n".join(queries) + "\n",
                           capture_output=True, text=True, timeout=900)
        assert r.returncode == 0 and r.stderr == "", r.stderr[-2000:]
        out = r.stdout.splitlines()
        assert len(out) == len(queries)
        for i, (c, tmax) in enumerate(vecs):
            for k, j in enumerate((0, 1, 2, 4)):
                words = out[4 * i + k].split()
                got = ((1, float(words[1]), words[2] == "1") if words[0] == "root" else
                       (0, math.nan, False) if words[0] == "noroot" else (-1, math.nan, False))
                if int(words[-1]) > LIMIT_NS:
                    slow.append(queries[4 * i + k])
                why = fuzz.check_answer(c, tmax, got[0], got[1])
                if why:
                    bad.append(f"{why}: {queries[4 * i + k]}")
                elif j in CROSS and not _same(ans[5 * i + j], got):
                    bad.append(f"C {ans[5 * i + j][:3]} vs Rust {got}: {queries[4 * i + k]}")
    if slow:  # time again: the machine is shared
        again = [subprocess.run([str(exe), "--time"], input="\n".join(slow) + "\n",
                                capture_output=True, text=True, timeout=300).stdout.splitlines()
                 for _ in range(3)]
        slow = [q for i, q in enumerate(slow) if min(int(a[i].split()[-1]) for a in again) > LIMIT_NS]
    assert not bad, f"{len(bad)} failures, first:\n" + "\n".join(bad[:10])
    assert not slow, f"{len(slow)} calls over 1 ms, first:\n" + "\n".join(slow[:10])


def select_backend(backend: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """max2code_runtime on its C ("c") or pure-Python ("python") backend for this test; no C
    backend: a skip, a failure in CI."""
    import max2code_runtime as rt
    c_backend = rt._load_c()
    if backend == "c" and c_backend is None:
        why = "the cffi backend is not built (python -m max2code_runtime.build)"
        if os.environ.get("CI"):
            pytest.fail(why + " -- required in CI")
        pytest.skip(why)
    monkeypatch.setattr(rt, "_C", c_backend if backend == "c" else None)


@pytest.mark.parametrize("backend", ["c", "python"])
def test_python_same_answers_as_c(c_answers, backend: str, monkeypatch: pytest.MonkeyPatch) -> None:
    import time

    import max2code_runtime as rt
    select_backend(backend, monkeypatch)
    limit = LIMIT_NS if backend == "c" else 50 * LIMIT_NS
    # the pure-Python port is slow: a tenth of the vectors (all of them on demand)
    share = 1 if backend == "c" or COUNT > 10000 else 10
    calls = (("interval", 0.0, 0), ("interval-nograze", 0.0, 1), ("closed", 0.0, 3), ("interval", SKIN, 4))
    bad, slow = [], []
    clock = time.thread_time_ns
    for vecs, _, ans in c_answers:
        for i, (c, tmax) in enumerate(vecs):
            if i % share:
                continue
            for method, eps, j in calls:
                def call():
                    return rt.first_root_status(c, tmax, method, eps)
                a = clock()
                got = call()
                if clock() - a > limit and min(_timed(call, clock) for _ in range(3)) > limit:
                    slow.append(f"{method} eps={eps}: c={c!r}, tmax={tmax!r}")
                why = fuzz.check_answer(c, tmax, got[0], got[1])
                if why:
                    bad.append(f"{why}: {method}, c={c!r}, tmax={tmax!r}")
                elif j in CROSS and not _same(ans[5 * i + j], got):
                    bad.append(f"C {ans[5 * i + j][:3]} vs Python {got}: {method}, c={c!r}, tmax={tmax!r}")
    assert not bad, f"{len(bad)} failures, first:\n" + "\n".join(bad[:10])
    assert not slow, f"{len(slow)} calls over {limit / 1e6:g} ms, first:\n" + "\n".join(slow[:10])


def _timed(call, clock) -> int:
    a = clock()
    call()
    return clock() - a


drivers = m2.drivers  # the Modula-2 and C drivers, linked with one object of the C runtime


def test_modula2_same_bits_as_c(c_answers, drivers: tuple[Path, Path]) -> None:
    """The Modula-2 binding on every fuzz vector and method: the C driver's answers, bit for
    bit (the fuzz batches were run by the C driver above; the M2 driver reads at most 17
    coefficients, as the C driver does)."""
    m2_exe = drivers[0]
    bad = []
    for vecs, _, ans in c_answers:
        lines = [m2.m2_line(m, c, t) for c, t in vecs for m in range(4)]
        got = [a for k in range(0, len(lines), M2_CHUNK)  # gm2's I/O is slow: chunks
               for a in m2.run_m2(m2_exe, lines[k:k + M2_CHUNK])]
        for i, (c, tmax) in enumerate(vecs):
            for m in range(4):
                if not _same(ans[5 * i + m], got[4 * i + m]):
                    bad.append(f"C {ans[5 * i + m][:3]} vs Modula-2 {got[4 * i + m]}: method {m}, "
                               f"c={c!r}, tmax={tmax!r}")
    assert not bad, f"{len(bad)} differences, first:\n" + "\n".join(bad[:10])
