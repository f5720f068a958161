"""bench/roots_ab.py, the interleaved A/B timing against a named baseline: what it says about the
answers must be right (a build against itself differs nowhere; a build whose roots are moved
by an ulp differs exactly where a root is found), and it must name a bad baseline clearly.
Its timings are not asserted (speed lives in the benchmark's output, not in tests)."""

from __future__ import annotations

import math
import re
import subprocess
import sys
from pathlib import Path

from conftest import ROOT, require

SCRIPT = ROOT / "bench" / "roots_ab.py"
C_SRC = ROOT / "runtime" / "c" / "max2code_roots.c"
FAMILIES = "generic8,noroot8,graze8,collision8"


def _run(*args: str) -> subprocess.CompletedProcess:
    require("gcc")
    return subprocess.run([sys.executable, str(SCRIPT), *args], capture_output=True, text=True,
                          cwd=ROOT, timeout=600)


def _rows(out: str) -> dict[str, list[float]]:
    rows = {}
    for line in out.splitlines():
        m = re.match(r"\| (\w+) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \|$", line)
        if m:
            rows[m.group(1)] = [float(x) for x in m.groups()[1:]]
    return rows


def test_the_runtime_against_itself_differs_nowhere() -> None:
    r = _run(str(C_SRC), "--count", "6", "--sweeps", "3", "--families", FAMILIES)
    assert r.returncode == 0, r.stderr
    assert "0 of 24 differ" in r.stdout
    rows = _rows(r.stdout)
    assert sorted(rows) == sorted(FAMILIES.split(","))
    assert all(a > 0 and b > 0 for a, b, _, _ in rows.values()), r.stdout


def test_warm_solves_reach_the_harness_and_change_no_answer() -> None:
    """--warm K: the harness itself reports the untimed solves it ran before each of B's timed
    ones (the report's words come from its output), and the answers are still compared."""
    r = _run(str(C_SRC), "--count", "4", "--sweeps", "2", "--warm", "2", "--families", FAMILIES)
    assert r.returncode == 0, r.stderr
    assert "timed after 2 untimed solves" in r.stdout and "0 of 16 differ" in r.stdout
    assert sorted(_rows(r.stdout)) == sorted(FAMILIES.split(","))
    cold = _run(str(C_SRC), "--count", "4", "--sweeps", "1", "--families", FAMILIES)
    assert cold.returncode == 0 and "untimed" not in cold.stdout
    bad = _run(str(C_SRC), "--count", "1", "--warm", "101", "--families", "generic8")
    assert bad.returncode == 2 and "--warm" in bad.stderr


def test_a_root_moved_by_an_ulp_is_reported_where_a_root_is_found(tmp_path: Path) -> None:
    src = C_SRC.read_text()
    marker = "    *t = root;\n"
    assert src.count(marker) == 1, "solve() no longer stores the root like this: adapt the test"
    moved = tmp_path / "moved.c"
    moved.write_text(src.replace(marker, "    *t = nextafter(root, INFINITY);\n"))
    r = _run(str(moved), "--count", "6", "--sweeps", "1", "--families", FAMILIES)
    assert r.returncode == 0, r.stderr
    m = re.search(r"(\d+) of 24 differ", r.stdout)
    assert m, r.stdout
    differ = [line.split() for line in r.stdout.splitlines() if line.strip().startswith("differ ")]
    # every generic octic, graze and found collision has a root; "no root" ones never differ
    assert int(m.group(1)) >= 12
    assert len(differ) == min(int(m.group(1)), 10)  # (the report lists the first ten)
    for _, _, sa, ta, _, sb, tb, _ in differ:  # A is the moved build: one ulp up, same status
        assert sa == sb == "1" and float.fromhex(ta) == math.nextafter(float.fromhex(tb), math.inf)


def test_a_bad_baseline_is_named() -> None:
    r = _run("no-such-revision", "--count", "1", "--families", "generic8")
    assert r.returncode != 0
    assert "no-such-revision" in r.stderr and "git revision" in r.stderr


def _instruction_rows(out: str) -> dict[str, list[float]]:
    rows = {}
    for line in out.splitlines():
        m = re.match(r"\| (\w+) \|" + r" ([\d.]+) \|" * 6 + "$", line)
        if m:
            rows[m.group(1)] = [float(x) for x in m.groups()[1:]]
    return rows


def test_instruction_counts_are_the_same_for_the_same_code_and_see_added_work(
        tmp_path: Path) -> None:
    """--instructions: the runtime against itself counts the same to 0.2 % (the point of the
    mode: no noise; timing differs by more than that from run to run), and a baseline doing 100 more multiply-adds per solve (a
    chain the compiler must keep: it feeds the answer) counts about that many more."""
    require("valgrind")
    r = _run(str(C_SRC), "--instructions", "--reps", "2", "--count", "5", "--families",
             "generic8,noroot8")
    assert r.returncode == 0, r.stderr
    rows = _instruction_rows(r.stdout)
    assert sorted(rows) == ["generic8", "noroot8"], r.stdout
    for ia, ib, _, ma, mb, _ in rows.values():
        # (A and B are two objects of one source: their code sits at different addresses)
        assert ia > 100 and abs(ib / ia - 1) <= 0.002 and abs(mb / ma - 1) <= 0.1, r.stdout
    unit = re.search(r"one degree-8 Horner evaluation = (\d+) instructions", r.stdout)
    assert unit and 20 <= int(unit.group(1)) <= 200, r.stdout

    src = C_SRC.read_text()
    marker = "    *t = root;\n"
    assert src.count(marker) == 1, "solve() no longer stores the root like this: adapt the test"
    busy = tmp_path / "busy.c"
    busy.write_text(src.replace(marker, "    for (int i = 0; i < 100; i++)\n"
                                "        root = root * (1 + 0x1p-60) + 0x1p-1074;\n" + marker))
    r = _run(str(busy), "--instructions", "--reps", "2", "--count", "5", "--families", "generic8")
    assert r.returncode == 0, r.stderr
    (ia, ib, *_), = _instruction_rows(r.stdout).values()
    assert 100 * 5 / 5 <= ia - ib <= 1000, r.stdout  # every generic octic has a root


def test_instructions_without_valgrind_say_so(tmp_path: Path) -> None:
    """No valgrind on PATH: a clear message naming it, not a traceback."""
    env = {"PATH": str(tmp_path), "HOME": str(tmp_path)}
    r = subprocess.run([sys.executable, str(SCRIPT), str(C_SRC), "--instructions", "--count",
                        "1", "--families", "generic8"], capture_output=True, text=True, cwd=ROOT,
                       env=env, timeout=600)
    assert r.returncode != 0
    assert "valgrind" in r.stderr and "Traceback" not in r.stderr
