"""No sign change, no root: the early exit of every runtime's solve (Descartes' rule of signs).

A polynomial whose nonzero coefficients all have one sign (zeros of either sign skipped) and
c_0 != 0 has no root in (0, inf).  The interval methods of C, Rust and Python return "no root"
for it right after reading the coefficients, before any preparation -- but only without a
contact skin (eps = 0): with one, the solve takes its full path.  Checked here:

* every runtime (the C driver, the Rust crate, Python's pure and C backends) gives status 0 on
  such polynomials -- among them one whose exponents span more than 2^1021 (the sliced path
  without the exit), tmax = inf, and -0.0 coefficients -- and the exact oracle
  (exact_roots.first_root, integer arithmetic on the doubles) agrees that there is none;
* the same polynomials with c_0's sign flipped (one sign change: exactly one positive root)
  are found by every runtime where the oracle has a root: the exit is not taken for them;
* the paths, by the cost accounting of the C runtime (-DM2C_COUNT) and of the ports (the Rust
  `count` feature; the pure-Python solver's events counted as test_python_control_flow does):
  C does no counted work at eps = 0 (the exit) and calls the derivative method where p(0) is
  within the skin (no exit); Rust's counters and Python's events equal C's on every call.
"""
from __future__ import annotations

import math
import subprocess
from pathlib import Path
from typing import Sequence

import pytest

from . import exact_roots as ex
from . import paths
from . import test_fuzz_runtimes as tf
from . import test_rust_runtime as rust
from .test_python_control_flow import _counting, _num, counts_driver  # noqa: F401

SKIN = tf.SKIN
INF = math.inf
CALLS = paths.CALLS

Vector = tuple[tuple[float, ...], float]

NO_CHANGE: list[Vector] = [
    ((1.0, 2.0, 3.0, 4.0), INF),
    ((-1.0, -0.0, -2.0, 0.0, -3e-5, -1.0), INF),
    ((2.0, -0.0, 1.0), INF),
    ((3.0, 1e-5), 10.0),
    ((0.25, 1.0, 0.5, 2.0, 1.0, 3.0, 1.0, 1.0, 4.0, 1.0, 1.0, 1.0, 5.0, 1.0, 1.0, 1.0, 1.0), 1e3),
    # exponents spanning 2^1993: first_root_sliced without the exit
    ((1e-300, -0.0, 0.0, 1e-10, 1e300), INF),
    ((-1e-300, -1e-200, -0.0, -1e300), 1e10),
    # p(0) within the skin: with eps > 0 the full path (the derivative method from 0)
    ((1e-12, 1e-3, 1.0, 1.0), INF),
    ((5e-10, -0.0, 1e-3, 1.0), INF),
    ((-1e-12, -0.0, -1e-6, -0.0, -1.0), INF),
    ((1e-300, 0.0, -0.0, 0.0, 0.0, 1e300), INF),
]
# c_0's sign flipped: one sign change, one positive root
ONE_CHANGE: list[Vector] = [((-c[0], *c[1:]), t) for c, t in NO_CHANGE]


def _sign_changes(c: Sequence[float]) -> int:
    signs = [x > 0 for x in c if x != 0]
    return sum(a != b for a, b in zip(signs, signs[1:]))


def _spread(c: Sequence[float]) -> int:
    e = [math.frexp(x)[1] for x in c if x != 0]
    return max(e) - min(e)


def test_the_vectors_are_what_they_claim() -> None:
    """No sign change and c_0 != 0, and the cases named above are among them."""
    assert all(_sign_changes(c) == 0 and c[0] != 0 for c, _ in NO_CHANGE)
    assert all(_sign_changes(c) == 1 for c, _ in ONE_CHANGE)
    assert any(math.copysign(1.0, x) < 0 and x == 0 for c, _ in NO_CHANGE for x in c)
    assert any(_spread(c) > 1021 and t == INF for c, t in NO_CHANGE)
    assert sum(abs(c[0]) <= SKIN for c, _ in NO_CHANGE) >= 4


@pytest.mark.parametrize("runtime", ["c", "rust", "python", "python-c"])
def test_every_runtime_against_the_oracle(runtime: str, tmp_path: Path,
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    vecs = NO_CHANGE + ONE_CHANGE
    kinds = [ex.first_root(c, tmax).kind for c, tmax in vecs]
    assert all(k == "none" for k in kinds[:len(NO_CHANGE)]), kinds
    roots = sum(k != "none" for k in kinds)
    rows = paths.judged(runtime, vecs, tmp_path, monkeypatch)
    bad = [str(r) for r in rows if not r.verdict.startswith("ok")]
    found = sum(r.answer[0] == 1 for r in rows)
    assert not bad, f"{runtime}:\n" + "\n".join(bad)
    # every flipped polynomial with a root in its window (all but one) has it found
    assert roots == len(ONE_CHANGE) - 1 and found == len(CALLS) * roots, (roots, found)


def test_paths_exit_only_without_skin(counts_driver: Path,  # noqa: F811 (the imported fixture)
                                      monkeypatch: pytest.MonkeyPatch) -> None:
    import max2code_runtime as rt
    from max2code_runtime import solver

    vecs = NO_CHANGE
    c_lines = [" ".join([str(m), repr(eps), _num(t), str(len(c) - 1), *(_num(x) for x in c)])
               for c, t in vecs for _, m, eps, _ in CALLS]
    r_lines = [" ".join([str(m), repr(eps), rust.fmt(t), str(len(c) - 1), *(rust.fmt(x) for x in c)])
               for c, t in vecs for _, m, eps, _ in CALLS]
    exe = rust.build_cli(rust.require_cargo(), "counts_cli", ("count",))
    outs = []
    for cmd, lines in (([str(counts_driver), "--madds"], c_lines), ([str(exe)], r_lines)):
        r = subprocess.run(cmd, input="\n".join(lines) + "\n", capture_output=True, text=True,
                           timeout=120)
        assert r.returncode == 0 and r.stderr == "", r.stderr[-2000:]
        outs.append([[int(x) for x in line.split()[3:]] for line in r.stdout.splitlines()])
        assert len(outs[-1]) == len(lines)
    c_counts, r_counts = outs
    monkeypatch.setattr(rt, "_C", None)
    events = _counting(solver, monkeypatch)
    py_counts = []
    for c, t in vecs:
        for method, _, eps, _ in CALLS:
            events[:] = [0] * len(events)
            rt.first_root_status(list(c), t, method, eps)
            py_counts.append(list(events))
    full = 0
    for k, line in enumerate(c_lines):
        (c, _), eps = vecs[k // len(CALLS)], CALLS[k % len(CALLS)][2]
        cc = c_counts[k]
        if eps == 0:
            assert not any(cc), f"C did work after its exit: {cc}: {line}"
        elif abs(c[0]) <= eps:
            assert cc[3] >= 1, f"C took no derivative method with p(0) in the skin: {cc}: {line}"
            full += 1
        assert r_counts[k] == cc, f"Rust {r_counts[k]} vs C {cc}: {line}"
        assert py_counts[k] == cc[:5], f"Python {py_counts[k]} vs C {cc[:5]}: {line}"
    assert full >= 4
