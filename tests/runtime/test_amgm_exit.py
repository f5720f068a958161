"""Step 0a': no root in (0, inf) when the AM-GM inequality shows every negative term outweighed.

With tmax = inf and no contact skin, a polynomial whose every negative coefficient (of
sign(c_0) c) stands alone between two positive ones a and b, with |c_i| below 2 sqrt(a b)
(less the graze envelope's margin; a positive coefficient between two negative ones lends half
of itself to each), is positive for every t > 0: the interval methods of C, Rust and Python
return "no root" right after reading the coefficients.  Checked here:

* the vectors are what they claim: the AM-GM condition holds (in exact arithmetic) for every
  OUTWEIGHED vector and fails for every NOT_OUTWEIGHED one, among which some are within 1e-12
  of the bound on either side, one has two roots, some touch within rounding;
* every runtime (the C driver, the Rust crate, Python's pure and C backends) answers every
  call right by the exact oracle (exact_roots.judge: integer arithmetic on the doubles) --
  the exit's "no root" included, and the full path's answer where the exit is refused;
* the paths: C does no counted work on the OUTWEIGHED vectors at eps = 0 (the exit) and some
  with a skin (no exit); the pure-Python solver's outweighed() says yes exactly on those;
  Rust's counters and Python's events equal C's on every vector (paths.assert_ports_take_c_path).
"""
from __future__ import annotations

import math
import random
import subprocess
from fractions import Fraction
from pathlib import Path
from typing import Sequence

import pytest

from . import exact_roots as ex
from . import paths
from .c_program import run_c_program
from .test_python_control_flow import _num, counts_driver  # noqa: F401

INF = math.inf
CALLS = paths.CALLS
Vector = tuple[tuple[float, ...], float]


def _m(a: float, b: float, delta: float) -> float:
    """2 sqrt(a b) (1 - delta), the negative coefficient at relative distance delta from the
    AM-GM bound of neighbours a and b."""
    return 2 * math.sqrt(a * b) * (1 - delta)


OUTWEIGHED: list[Vector] = [
    ((1.0, -_m(1, 1, 0.5), 1.0, 0.5), INF),
    ((1.0, -_m(1, 1, 1e-3), 1.0, 0.5), INF),
    ((1.0, -_m(1, 1, 1e-12), 1.0, 1e-9), INF),
    # c_2 lends half of itself to each of its negative neighbours
    ((1.0, -_m(1, 0.5, 1e-6), 1.0, -_m(0.5, 1, 1e-6), 1.0), INF),
    # c_0 < 0: the same test on -c
    ((-3.0, 2.0, -1.0, -0.5), INF),
    ((1.0, -1.0, 1.0, -1.0, 1.0), INF),  # (t^5 + 1) / (t + 1): c_2 lends 1/2 to each side
    # the separating pairs' pattern of bench/roots.py's "no root, tmax = inf" family
    ((0.5, -0.3, 0.4, -0.2, 0.3, -0.1, 0.2, -0.05, 0.1), INF),
    ((2.0, 1.0, -0.5, 1.0, 3.0, 1.0, -1.0, 2.0, 4.0, 1.0, 1.0, -0.1, 1.0), INF),
    ((1.0, -1.0, 1.0, 0.0, 0.0, 2.0, -1.0, 1.0, 0.5, 0.25, 1.0, 1.0, 0.5, 1.0, -1.0, 1.0, 1.0), INF),
    # hostile magnitudes: 2 sqrt(a) sqrt(b) overflows (a true inequality), or all tiny
    ((1.5e308, -1.7e308, 1.5e308, 1.0), INF),
    ((1e300, -1.9e300, 1e300, 1e300), INF),
    ((1e-300, -1.9e-300, 1e-300, 1e-300), INF),
    ((4e-310, -7e-310, 4e-310, 1.0), INF),  # subnormal neighbours
]

NOT_OUTWEIGHED: list[Vector] = [
    ((1.0, -_m(1, 1, -1e-3), 1.0, 1e-9), INF),    # two roots near 1
    ((1.0, -_m(1, 1, -1e-12), 1.0, 1e-20), INF),  # a dip of 1e-12: two roots, or a touch
    ((1.0, -_m(1, 1, 1e-16), 1.0, 1e-20), INF),   # inside the envelope's margin: no exit
    ((1.0, -_m(1, 1, 0.0), 1.0, 1e-20), INF),     # a double root at 1, within rounding
    ((1.0, -0.1, -0.1, 1.0), INF),                # two negatives side by side
    ((1.0, 0.0, -1e-3, 1.0, 1.0), INF),           # a zero beside a negative
    ((1.0, -1.5, 1.0, -1.5, 1.0), INF),           # c_2 cannot lend 1/2 to both: touch at 1
    ((1.0, -_m(1, 1, 0.5), 1.0, -0.5), INF),      # c_n of the other sign: a root
    ((1.0, -_m(1, 1, 0.5), 1.0, 0.5), 10.0),      # outweighed, but the exit is for tmax = inf
]


def _amgm_exact(c: Sequence[float]) -> bool:
    """The AM-GM condition in exact arithmetic, without the envelope's margin: every negative
    coefficient isolated between positive a, b (each halved when it serves two) with
    c_i^2 < 4 a b."""
    s = -1 if c[0] < 0 else 1
    q = [Fraction(s * x) for x in c]
    n = len(q) - 1
    if not q[n] > 0:
        return False
    for i in range(1, n):
        if q[i] >= 0:
            continue
        if not (q[i - 1] > 0 and q[i + 1] > 0):
            return False
        a = q[i - 1] / (2 if i >= 2 and q[i - 2] < 0 else 1)
        b = q[i + 1] / (2 if i + 2 <= n and q[i + 2] < 0 else 1)
        if not q[i] ** 2 < 4 * a * b:
            return False
    return True


def test_the_vectors_are_what_they_claim() -> None:
    assert all(_amgm_exact(c) and t == INF for c, t in OUTWEIGHED)
    # refused: the condition fails exactly, or holds only within the margin, or tmax is finite
    margin = [c for c, t in NOT_OUTWEIGHED if _amgm_exact(c)]
    assert [t for c, t in NOT_OUTWEIGHED if _amgm_exact(c)] == [INF, 10.0], margin
    kinds = [ex.first_root(c, t).kind for c, t in NOT_OUTWEIGHED]
    assert kinds.count("none") >= 4 and len(kinds) - kinds.count("none") >= 3, kinds
    assert any(len(c) == 17 for c, _ in OUTWEIGHED) and any(x != 0 and abs(x) < 2.3e-308
                                                           for c, _ in OUTWEIGHED for x in c)


@pytest.mark.parametrize("runtime", ["c", "rust", "python", "python-c"])
def test_every_runtime_against_the_oracle(runtime: str, tmp_path: Path,
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    assert all(ex.first_root(c, tmax).kind == "none" for c, tmax in OUTWEIGHED)
    # right by the oracle, and on OUTWEIGHED without a skin "no root" itself
    bad = [str(r) for r in paths.judged(runtime, OUTWEIGHED + NOT_OUTWEIGHED, tmp_path, monkeypatch)
           if not r.verdict.startswith("ok") or (r.index < len(OUTWEIGHED) and r.eps == 0
                                                  and r.answer[0] != 0)]
    assert not bad, f"{runtime}:\n" + "\n".join(bad)


def test_paths(counts_driver: Path,  # noqa: F811 (the imported fixture)
               monkeypatch: pytest.MonkeyPatch) -> None:
    # C: no counted work at eps = 0 on the OUTWEIGHED vectors, some with a skin (full path)
    lines = [" ".join([str(m), repr(eps), _num(t), str(len(c) - 1), *(_num(x) for x in c)])
             for c, t in OUTWEIGHED for _, m, eps, _ in CALLS]
    r = subprocess.run([str(counts_driver), "--madds"], input="\n".join(lines) + "\n",
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and r.stderr == "", r.stderr[-2000:]
    rows = [[int(x) for x in line.split()[3:]] for line in r.stdout.splitlines()]
    assert len(rows) == len(lines)
    skin_work = 0
    for line, cc in zip(lines, rows):
        if float(line.split()[1]) == 0:
            assert not any(cc), f"C did work after its exit: {cc}: {line}"
        else:
            skin_work += any(cc)
    assert skin_work >= len(OUTWEIGHED) // 2, skin_work
    # Python: outweighed() says yes on exactly the OUTWEIGHED vectors it is asked about
    vecs = OUTWEIGHED + NOT_OUTWEIGHED
    for (c, t), said in zip(vecs, paths.python_returns("outweighed", vecs, monkeypatch)):
        assert said == ([True] if (c, t) in OUTWEIGHED else [] if t < INF else [False]), (c, t, said)
    # Rust and Python take C's path on every vector
    paths.assert_ports_take_c_path(counts_driver, OUTWEIGHED + NOT_OUTWEIGHED, monkeypatch)



OUTWEIGHED_PROGRAM = r"""
#include "max2code_roots.c"
#include <stdio.h>
#include <stdlib.h>

/* stdin: a line per vector, N EXPECTED C0 .. CN (hex floats); prints the differences */
int main(void)
{
    long bad = 0, total = 0;
    char line[4096];
    while (fgets(line, sizeof line, stdin)) {
        char *p = line, *end;
        int n = (int)strtol(p, &end, 10);
        int want = (int)strtol(end, &p, 10);
        double c[MAXN + 1];
        for (int i = 0; i <= n; i++) {
            c[i] = strtod(p, &end);
            p = end;
        }
        total++;
        if (outweighed(c, n) != want && bad++ < 10)
            printf("differ: %s", line);
    }
    printf("%ld vectors\n%ld differences\n", total, bad);
    return 0;
}
"""


def _amgm_vectors(count: int, seed: int) -> list[tuple[float, ...]]:
    """Random vectors for outweighed(): degrees 3-16, signs alternating (the test's pattern) or
    any, zeros now and then, magnitudes over 2^+-20, and every negative coefficient between two
    positive ones moved to within 1e-3 or 1e-14 of its AM-GM bound (just above or below)."""
    rng = random.Random(seed)
    out = []
    for _ in range(count):
        n = rng.randint(3, 16)
        s = rng.choice((-1.0, 1.0))
        alt = rng.random() < 0.7
        c = []
        for i in range(n + 1):
            neg = i > 0 and (i % 2 == 1 and rng.random() < 0.6 if alt else rng.random() < 0.35)
            mag = math.ldexp(1 + rng.random(), rng.randint(-20, 19))
            c.append(0.0 if i > 0 and rng.random() < 0.03 else s * (-mag if neg else mag))
        for i in range(1, n):
            if not (s * c[i] < 0 < s * c[i - 1] and s * c[i + 1] > 0):
                continue
            a = s * c[i - 1] * (0.5 if i >= 2 and s * c[i - 2] < 0 else 1.0)
            b = s * c[i + 1] * (0.5 if i + 2 <= n and s * c[i + 2] < 0 else 1.0)
            d = (rng.random() - 0.5) * rng.choice((1e-3, 1e-14))
            c[i] = -s * 2 * math.sqrt(a) * math.sqrt(b) * (1 - 2e-15 * n + d)
        out.append(tuple(c))
    return out


def test_outweighed_decides_as_the_loop_it_replaced(tmp_path: Path) -> None:
    """C's outweighed() reads the signs as bit masks and makes every comparison without an exit;
    the pure-Python port keeps the loop it replaced (a branch on each sign, an exit at the first
    failure: the same arithmetic).  On 100,000 random vectors near the AM-GM bound C decides as
    Python does, and both answers occur often enough to mean something."""
    from max2code_runtime import solver
    vecs = _amgm_vectors(100_000, 20261203)
    want = [solver.outweighed(c, len(c) - 1) for c in vecs]
    assert 0.05 * len(vecs) < sum(want) < 0.95 * len(vecs), sum(want)
    lines = [" ".join([str(len(c) - 1), str(int(w)), *(x.hex() for x in c)])
             for c, w in zip(vecs, want)]
    out = run_c_program(OUTWEIGHED_PROGRAM, tmp_path, "outweighed", "\n".join(lines) + "\n")
    assert out.split("\n")[0] == "100000 vectors", out
