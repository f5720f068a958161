"""The Rust runtime takes the C solver's path, step for step, not only its answers.

Answers are robust to a skipped step (a root is polished to the last bit from any bracket),
so test_fuzz_runtimes' bit-for-bit comparison cannot tell a faithful port from one that, say,
never speculates or never halves in the Bernstein basis.  Here the C runtime is built with
its cost accounting (-DM2C_COUNT, tests/runtime/counts_driver.c --madds) and the Rust one
with the same counters at the same places (cargo feature `count`, examples/counts_cli.rs),
and for every solve the two must agree on the status, the root's bits, the graze flag, the
events (Newton steps with plain and with compensated evaluation, Taylor points,
derivative-method calls, Bernstein tests) and the multiply-adds by phase -- which also count
the speculative Newton steps and the de Casteljau halvings of the Bernstein exclusion, which
no event marks.

Inputs as in test_python_control_flow (hard cases, random polynomials, every benchmark
family, fuzz vectors; each with and without the graze check and with a contact skin);
M2C_FLOW_COUNT sets their number (default 300: a few seconds).
"""
from __future__ import annotations

import subprocess
from pathlib import Path

from . import test_rust_runtime as rust
from .test_python_control_flow import CALLS, EVENTS, _inputs, _num, counts_driver  # noqa: F401

PHASES = ("preparation", "counts and exclusion tests", "Newton polishing and speculation",
          "derivative method")


def _rust_num(x: float) -> str:
    return repr(float(x))  # 'inf' and 'nan' parse in Rust too


def test_rust_takes_c_path(counts_driver: Path) -> None:  # noqa: F811 (the imported fixture)
    exe = rust.build_cli(rust.require_cargo(), "counts_cli", ("count",))
    c_lines, r_lines = [], []
    for c, tmax in _inputs():
        for _, number, eps in CALLS:
            head = [str(number), repr(eps)]
            c_lines.append(" ".join([*head, _num(tmax), str(len(c) - 1), *(_num(x) for x in c)]))
            r_lines.append(" ".join([*head, _rust_num(tmax), str(len(c) - 1), *(_rust_num(x) for x in c)]))
    outs = []
    for cmd, lines in (([str(counts_driver), "--madds"], c_lines), ([str(exe)], r_lines)):
        r = subprocess.run(cmd, input="\n".join(lines) + "\n", capture_output=True, text=True,
                           timeout=600)
        assert r.returncode == 0 and r.stderr == "", r.stderr[-2000:]
        outs.append(r.stdout.splitlines())
        assert len(outs[-1]) == len(lines)
    names = EVENTS + tuple(f"multiply-adds in {p}" for p in PHASES)
    bad, speculated, halved = [], 0, 0
    for line, ctext, rtext in zip(c_lines, *outs):
        cw, rw = ctext.split(), rtext.split()
        c_ans = (int(cw[0]), float.fromhex(cw[1]).hex(), cw[2])
        r_ans = (int(rw[0]), float(rw[1]).hex(), rw[2])
        cev, rev = [int(x) for x in cw[3:]], [int(x) for x in rw[3:]]
        if c_ans != r_ans:
            bad.append(f"answer: C {c_ans} vs Rust {r_ans}: {line}")
        elif cev != rev:
            diff = ", ".join(f"{k} C {a} Rust {b}" for k, a, b in zip(names, cev, rev) if a != b)
            bad.append(f"path: {diff}: {line}")
        # coverage of the paths no event marks: a root after the speculation and one
        # Bernstein test, no Taylor point (its certificate, or the whole window's test after a
        # guess that gave up: test_python_control_flow.py tells them apart, on the same
        # paths), and a window cleared by halvings (one test, no point, no Newton step, more
        # phase-1 work than the degree's exclusion test and Bernstein test without them: n +
        # (n (n + 1) / 2 + 4 n) + n (n + 1) / 2)
        n = int(line.split()[3])
        plain, precise, points, deriv, bern, m0, m1, m2, m3 = cev
        speculated += c_ans[0] == 1 and points == 0 and bern == 1 and m2 > 0
        halved += (c_ans[0] == 0 and points == 0 and bern == 1 and plain + precise == 0
                   and m1 > 5 * n + n * (n + 1))
    assert not bad, f"{len(bad)} of {len(c_lines)} solves differ, first:\n" + "\n".join(bad[:10])
    assert speculated > len(c_lines) // 20, f"only {speculated} certified speculations"
    assert halved > 0, "no window cleared by Bernstein halvings"
