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
import subprocess
from fractions import Fraction
from pathlib import Path
from typing import Sequence

import pytest

from . import exact_roots as ex
from . import paths
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

static unsigned long long state = 0x9E3779B97F4A7C15ULL;
static double uni(void) /* [0, 1) */
{
    state ^= state << 13; state ^= state >> 7; state ^= state << 17;
    return (double)(state >> 11) / 9007199254740992.0;
}

/* The definition: every i, a branch on its sign, an exit at the first failure. */
static int reference(const double c[], int n)
{
    double s = c[0] < 0 ? -1 : 1, e = 2 * noise_factor(n);
    double K = (1 + e) / (1 - e) * (1 + 16 * UNIT_ROUNDOFF);
    if (!(s * c[n] > 0))
        return 0;
    for (int i = 1; i < n; i++) {
        double v = s * c[i];
        if (!(v < 0))
            continue;
        double a = s * c[i - 1], b = s * c[i + 1];
        if (!(a > 0 && b > 0))
            return 0;
        a *= i >= 2 && s * c[i - 2] < 0 ? 0.5 : 1;
        b *= i + 2 <= n && s * c[i + 2] < 0 ? 0.5 : 1;
        if (!(-v * K < 2 * (sqrt(a) * sqrt(b))))
            return 0;
    }
    return 1;
}

int main(void)
{
    long bad = 0, yes = 0, total = 0;
    for (int k = 0; k < 400000; k++) {
        int n = 3 + (int)(uni() * 14); /* 3 .. 16 */
        double c[MAXN + 1], s = uni() < 0.5 ? -1 : 1;
        /* signs: alternating often (the AM-GM pattern), else any, zeros now and then */
        int alt = uni() < 0.7;
        for (int i = 0; i <= n; i++) {
            double r = uni();
            int sg = i == 0 ? 1 : alt ? (i % 2 && r < 0.6 ? -1 : 1) : (r < 0.35 ? -1 : 1);
            double mag = ldexp(1 + uni(), (int)(uni() * 40) - 20);
            c[i] = uni() < 0.03 ? 0.0 : s * sg * mag;
        }
        c[0] = c[0] == 0 ? s : c[0];
        /* negatives near their AM-GM bound, 2 sqrt(a b) h (1 + d), |d| small or tiny */
        for (int i = 1; i < n; i++) {
            if (!(s * c[i] < 0) || !(s * c[i - 1] > 0) || !(s * c[i + 1] > 0))
                continue;
            double a = s * c[i - 1] * (i >= 2 && s * c[i - 2] < 0 ? 0.5 : 1);
            double b = s * c[i + 1] * (i + 2 <= n && s * c[i + 2] < 0 ? 0.5 : 1);
            double d = (uni() - 0.5) * (uni() < 0.5 ? 1e-3 : 1e-14);
            c[i] = -s * 2 * sqrt(a) * sqrt(b) * (1 - 2e-15 * n + d);
        }
        int want = reference(c, n), got = outweighed(c, n);
        total++;
        yes += want;
        if (want != got) {
            if (bad++ < 10) {
                printf("differ n=%d reference %d outweighed %d:", n, want, got);
                for (int i = 0; i <= n; i++)
                    printf(" %a", c[i]);
                printf("\n");
            }
        }
    }
    printf("%ld vectors, %ld outweighed\n%ld differences\n", total, yes, bad);
    return 0;
}
"""


def test_outweighed_decides_as_its_definition(tmp_path: Path) -> None:
    """C's outweighed() reads the signs as bit masks and makes every comparison without an exit:
    on 400,000 random vectors (degrees 3-16, alternating signs or any, zeros, negatives within
    1e-3 and 1e-14 of their AM-GM bound) it says what the loop it replaced (its definition,
    written out here: a branch on each sign, an exit at the first failure) says, and both
    answers occur often enough to mean something."""
    from .c_program import run_c_program
    out = run_c_program(OUTWEIGHED_PROGRAM, tmp_path, "outweighed")
    total, yes = (int(w) for w in out.split("\n")[0].split()[0:3:2])
    assert total == 400000 and 0.05 * total < yes < 0.95 * total, out
