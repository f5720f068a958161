"""One solve per vector through C's counting driver, the Rust crate's counting CLI and the
pure-Python solver's event hooks: the answers and the cost accounting of each, so that a test
can assert that C took a given path and that both ports took the same one (the same Newton
steps, Taylor points, derivative-method calls, Bernstein tests and multiply-adds by phase)."""

from __future__ import annotations

import math
import subprocess
from pathlib import Path
from typing import NamedTuple, Sequence

import pytest

from . import exact_roots as ex
from . import test_fuzz_runtimes as tf
from . import test_rust_runtime as rust
from .spy import patch_solver
from .test_python_control_flow import _counting, _num

Vector = tuple[tuple[float, ...], float]

# The interval method's calls: (Python method, C method, eps, Rust roots_cli method)
CALLS = (("interval", 0, 0.0, "interval"), ("interval-nograze", 1, 0.0, "nograze"),
         ("interval", 0, tf.SKIN, f"skin:{tf.SKIN!r}"))


Call = tuple[str, int, float, str]


def answers(runtime: str, vecs: Sequence[Vector], tmp: Path,
            monkeypatch: pytest.MonkeyPatch | None = None,
            calls: Sequence[Call] = CALLS) -> list[tuple[int, float, bool]]:
    """(status, root, graze) of every call in `calls` (CALLS unless given) on every vector,
    vector by vector, from "c" (the plain C driver), "rust" (roots_cli), "python" or "python-c"
    (the pure-Python solver, or the C runtime through cffi; these two need monkeypatch)."""
    if runtime == "c":
        driver = tf.build_driver(tmp / "roots_driver")
        lines = [tf.c_line(f"{m}:{eps!r}" if eps else m, c, t) for c, t in vecs for _, m, eps, _ in calls]
        return [a[:3] for a in tf.run_timed(driver, lines)]
    if runtime == "rust":
        exe = rust.build_cli(rust.require_cargo())
        queries = [f"{name} {rust.fmt(t)} {' '.join(rust.fmt(x) for x in c)}"
                   for c, t in vecs for *_, name in calls]
        out = subprocess.run([str(exe)], input="\n".join(queries) + "\n", capture_output=True,
                             text=True, timeout=120, check=True).stdout.splitlines()
        assert len(out) == len(queries)
        got = []
        for line in out:
            w = line.split()
            got.append((1, float(w[1]), w[2] == "1") if w[0] == "root" else
                       (0, math.nan, False) if w[0] == "noroot" else (-1, math.nan, False))
        return got
    import max2code_runtime as rt

    assert monkeypatch is not None, "the Python runtimes are selected through monkeypatch"
    tf.select_backend("python" if runtime == "python" else "c", monkeypatch)
    return [rt.first_root_status(list(c), t, method, eps) for c, t in vecs for method, _, eps, _ in calls]


class Judged(NamedTuple):
    """One call of CALLS on one vector, and the exact oracle's verdict on its answer."""
    index: int  # the vector's
    c: tuple[float, ...]
    tmax: float
    method: str
    eps: float
    answer: tuple[int, float, bool]  # (status, root, graze)
    verdict: str  # exact_roots.judge's: "ok..." or what is wrong

    def __str__(self) -> str:
        return (f"{self.verdict}: {self.method} eps={self.eps} gave {self.answer} for "
                f"c={self.c!r}, tmax={self.tmax!r}")


def judged(runtime: str, vecs: Sequence[Vector], tmp: Path,
           monkeypatch: pytest.MonkeyPatch | None = None) -> list[Judged]:
    """Every call of CALLS on every vector through `runtime` (answers()), judged by the exact
    oracle (exact_roots.judge: integer arithmetic on the doubles)."""
    got = answers(runtime, vecs, tmp, monkeypatch)
    out = []
    for i, (c, tmax) in enumerate(vecs):
        for j, (method, _, eps, _) in enumerate(CALLS):
            st, t, g = got[len(CALLS) * i + j]
            out.append(Judged(i, tuple(c), tmax, method, eps, (st, t, g),
                              ex.judge(c, tmax, st, t, g, eps)))
    return out


def _run(cmd: list[str], lines: list[str]) -> list[list[str]]:
    r = subprocess.run(cmd, input="\n".join(lines) + "\n", capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and r.stderr == "", r.stderr[-2000:]
    rows = [line.split() for line in r.stdout.splitlines()]
    assert len(rows) == len(lines)
    return rows


def c_rows(driver: Path, vecs: Sequence[Vector]) -> list[list[str]]:
    """The default method on each vector: STATUS T(%a) GRAZE PLAIN PRECISE POINTS DERIVATIVE
    BERNSTEIN MADDS0..MADDS3 (tests/runtime/counts_driver.c --madds)."""
    lines = [" ".join(["0", "0", _num(t), str(len(c) - 1), *(_num(x) for x in c)]) for c, t in vecs]
    return _run([str(driver), "--madds"], lines)


class CSolve(NamedTuple):
    """One row of c_rows, parsed: the answer and C's counted events."""
    status: int
    t: float
    graze: bool
    plain: int  # Newton steps with plain evaluation
    precise: int  # and with compensated evaluation
    points: int  # Taylor points
    derivative: int  # derivative-method calls
    bernstein: int  # Bernstein tests
    madds: tuple[int, ...]  # multiply-adds by phase

    @property
    def path(self) -> tuple[int, int, int, int]:
        """(status, Taylor points, derivative-method calls, Bernstein tests): which way C went."""
        return self.status, self.points, self.derivative, self.bernstein


def c_solves(driver: Path, vecs: Sequence[Vector]) -> list[CSolve]:
    """c_rows, parsed."""
    return [CSolve(int(r[0]), float.fromhex(r[1]), r[2] == "1", *(int(x) for x in r[3:8]),
                   tuple(int(x) for x in r[8:])) for r in c_rows(driver, vecs)]


def assert_ports_take_c_path(driver: Path, vecs: Sequence[Vector],
                             monkeypatch: pytest.MonkeyPatch) -> None:
    """Rust's answers and counters equal C's on every vector, and so do the pure-Python
    solver's answers and events."""
    import max2code_runtime as rt
    from max2code_runtime import solver

    c = c_rows(driver, vecs)
    exe = rust.build_cli(rust.require_cargo(), "counts_cli", ("count",))
    r = _run([str(exe)], [" ".join(["0", "0", rust.fmt(t), str(len(cs) - 1), *(rust.fmt(x) for x in cs)])
                          for cs, t in vecs])
    monkeypatch.setattr(rt, "_C", None)
    events = _counting(solver, monkeypatch)
    for (coeffs, tmax), cr, rr in zip(vecs, c, r):
        # (counts_cli prints the root in decimal, the C driver as %a: compared as numbers)
        same = rr[0] == cr[0] and rr[2:] == cr[2:] and (
            cr[0] != "1" or float(rr[1]) == float.fromhex(cr[1]))
        assert same, f"Rust {rr} vs C {cr}: c={coeffs!r}, tmax={tmax!r}"
        events[:] = [0] * len(events)
        st, t, graze = rt.first_root_status(list(coeffs), tmax, "interval", 0.0)
        assert (st, t if st == 1 else 0.0, int(graze)) == (int(cr[0]), float.fromhex(cr[1]), int(cr[2])), \
            f"Python {(st, t, graze)} vs C {cr[:3]}: c={coeffs!r}, tmax={tmax!r}"
        assert events == [int(x) for x in cr[3:8]], \
            f"Python {events} vs C {cr[3:8]}: c={coeffs!r}, tmax={tmax!r}"


def python_returns(name: str, vecs: Sequence[Vector],
                   monkeypatch: pytest.MonkeyPatch) -> list[list[object]]:
    """What the pure-Python solver's function `name` returned in the default solve of each
    vector, call by call: where a test asserts which way the solver went."""
    import max2code_runtime as rt
    from max2code_runtime import solver

    seen: list[object] = []
    inner = getattr(solver, name)

    def spy(*args: object) -> object:
        seen.append(inner(*args))
        return seen[-1]
    patch_solver(monkeypatch, name, spy)
    monkeypatch.setattr(rt, "_C", None)
    out = []
    for c, tmax in vecs:
        seen.clear()
        rt.first_root_status(list(c), tmax, "interval", 0.0)
        out.append(list(seen))
    monkeypatch.undo()
    return out
