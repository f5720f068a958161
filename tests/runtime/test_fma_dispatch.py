"""The precise kernels' fma-instruction copies against their plain builds, bit for bit.

Built without -mfma (the default on x86-64), the C runtime compiles its precise kernels twice --
fma Horner and the compensated Horner, with and without the slope -- once for the fma
instruction and once plainly (fma() a library call, the error-free product by Dekker's
splitting), and picks one per call by the CPU (FMA_DISPATCH in max2code_roots.c).  The promise
is the same bits either way: fma is correctly rounded as an instruction or a call, and both
error-free products are exact.  So the answers cannot depend on the machine, and the Rust and
Python ports (which do not dispatch the same way, or at all) agree with C everywhere.

The touch's scan reads five evaluations computed in one loop (touch_values): checked here
against the kernels it replaces, in both copies.

A program that includes max2code_roots.c evaluates random polynomials of every degree at
random points and at points a few ulps from their roots (where the compensated value is all
correction, and any slip in the error terms shows), with both copies, and prints every
difference.  Where the CPU has no fma instruction the copies cannot both run: skipped locally
with that reason.  (The whole runtime built with -DM2C_NO_FMA_DISPATCH, the plain kernels only,
answers as the default build: tests/runtime/test_build_variants.py.)
"""
from __future__ import annotations

import platform
from pathlib import Path

import pytest

from .c_program import run_c_program

PROGRAM = r"""
#include "max2code_roots.c"
#include <stdio.h>
#include <stdlib.h>

#if !FMA_DISPATCH
int main(void) { printf("no dispatch in this build\n"); return 3; }
#else
static unsigned long long state = 0x2545F4914F6CDD1DULL;
static double uni(void) /* [0, 1) */
{
    state ^= state << 13; state ^= state >> 7; state ^= state << 17;
    return (double)(state >> 11) / 9007199254740992.0;
}

static int bad = 0;
static long compared = 0;
static void same(double a, double b, const char *what, int m, double x)
{
    compared++;
    if (memcmp(&a, &b, sizeof a) != 0) {
        bad++;
        if (bad < 20)
            printf("%s m=%d x=%a: %a (fma) vs %a (plain)\n", what, m, x, a, b);
    }
}

int main(void)
{
    if (!__builtin_cpu_supports("fma")) {
        printf("this CPU has no fma instruction\n");
        return 4;
    }
    for (int trial = 0; trial < 40000; trial++) {
        int m = 1 + trial % MAXN;
        double P[MAXN + 1], D[MAXN + 1], r[MAXN];
        /* from roots (some close together), so that points near a root exist */
        for (int i = 0; i < m; i++)
            r[i] = (uni() < 0.5 ? -1 : 1) * ldexp(0.5 + uni(), (int)(uni() * 8) - 4);
        if (trial % 3 == 0 && m >= 2)
            r[1] = r[0] * (1 + ldexp(uni(), -20));
        P[0] = 1;
        for (int i = 1; i <= m; i++)
            P[i] = 0;
        for (int i = 0; i < m; i++) /* times (t - r_i) */
            for (int j = i + 1; j >= 0; j--)
                P[j] = (j > 0 ? P[j - 1] : 0) - r[i] * P[j];
        double scale = ldexp(1.0, (int)(uni() * 40) - 20);
        for (int i = 0; i <= m; i++)
            P[i] *= scale;
        for (int i = 0; i < m; i++)
            D[i] = (i + 1) * P[i + 1];
        for (int s = 0; s < 4; s++) {
            double x = s == 0 ? r[0] * (1 + ldexp(uni() - 0.5, -50))
                     : s == 1 ? r[(int)(uni() * m)]
                     : (uni() - 0.5) * 8;
            same(compensated_hw(P, m, x), compensated_core(P, m, x, 0), "compensated", m, x);
            double s1, s2;
            double v1 = compensated_slope_hw(P, D, m, x, &s1);
            double v2 = compensated_slope_core(P, D, m, x, &s2, 0);
            same(v1, v2, "compensated_with_slope", m, x);
            same(s1, s2, "its slope", m, x);
            for (int k = 0; k <= 2; k++) /* k != 0: the scaled form */
                same(horner_fma_hw(P, m, x, k), horner_core(P, m, x, k, 1), "horner_fma", m, x);
            if (m >= 3) {
                /* touch_values: the five evaluations of a touch's scan in one loop, against
                 * the kernels it replaces (dispatched) and its plain copy */
                double D2[MAXN + 1], hi = x * (1 + ldexp(uni(), -8)), sl;
                for (int i = 0; i < m - 1; i++)
                    D2[i] = (i + 1) * D[i + 1];
                TouchValues tv, tp;
                touch_values(P, D, D2, m, x, hi, &tv);
                touch_values_core(P, D, D2, m, x, hi, &tp, 0);
                double want[6] = {horner(P, m, x, 0, 1), horner_compensated(P, m, x),
                                  horner_abs(P, m, x, 0), horner(P, m, hi, 0, 1),
                                  compensated_with_slope(D, D2, m - 1, x, &sl), 0};
                want[5] = sl;
                double got[6] = {tv.vb, tv.pb, tv.ab, tv.vhi, tv.dv, tv.ddv};
                double plain[6] = {tp.vb, tp.pb, tp.ab, tp.vhi, tp.dv, tp.ddv};
                for (int i = 0; i < 6; i++) {
                    same(got[i], want[i], "touch_values", m, x);
                    same(plain[i], want[i], "touch_values (plain copy)", m, x);
                }
            }
        }
    }
    printf("%ld values compared\n%d differences\n", compared, bad);
    return bad != 0;
}
#endif
"""


def test_fma_copies_give_the_plain_bits(tmp_path: Path) -> None:
    if platform.machine() not in ("x86_64", "AMD64", "i386", "i686"):
        pytest.skip(f"no fma dispatch on {platform.machine()}: the runtime has one build there")
    if "fma" not in Path("/proc/cpuinfo").read_text().split():
        pytest.skip("this CPU has no fma instruction: only the plain kernels can run here")
    out = run_c_program(PROGRAM, tmp_path, "fma_dispatch")
    compared = int(out.split("values compared")[0].split()[-1])
    # 6 per point, and 12 more per point from degree 3 on (touch_values and its plain copy)
    touch = sum(1 for trial in range(40000) if 1 + trial % 16 >= 3)
    assert compared == 40000 * 4 * 6 + touch * 4 * 12, out
