"""The C runtime's written-out kernels against plain loops and exact integer arithmetic.

Up to degree 8 the solver's inner kernels are written out (no loop bounds that vary with the
degree): the Bernstein conversion's running sums, de Casteljau halving and the Taylor shift at a
point.  Each promises the same values as the obvious loop, bit for bit, so that the Python port
(which uses the loops) and the Rust one (fixed-size forms of its own, checked against the loops
by its unit tests) agree with C exactly.  The preparation reads exponents from
the bits and rounds a quotient up by a multiply instead of a division.  A program that includes
max2code_roots.c checks each against its definition on random and edge data; any difference is
printed and fails the test.
"""
from __future__ import annotations

from pathlib import Path

from .c_program import run_c_program


PROGRAM = r"""
#include "max2code_roots.c"
#include <stdio.h>
#include <stdlib.h>

static unsigned long long state = 0x9E3779B97F4A7C15ULL;
static double rnd(void) /* wide range, both signs, some exact zeros */
{
    state ^= state << 13; state ^= state >> 7; state ^= state << 17;
    int kind = (int)(state % 16);
    double m = (double)(state >> 11) / 9007199254740992.0 - 0.5;
    if (kind == 0)
        return 0.0;
    return ldexp(m, (int)((state >> 5) % 60) - 30);
}

static int bad = 0;
#define CHECK(cond, ...) do { if (!(cond)) { bad++; if (bad < 20) printf(__VA_ARGS__); } } while (0)

int main(void)
{
    /* ceil_div: every numerator and denominator it is used for */
    for (int den = 1; den <= MAXN; den++)
        for (int num = -4095; num <= 4095; num++) {
            int q = num >= 0 ? (num + den - 1) / den : -((-num) / den);
            CHECK(ceil_div(num, den) == q, "ceil_div(%d, %d) = %d, not %d\n", num, den,
                  ceil_div(num, den), q);
        }
    for (int trial = 0; trial < 20000; trial++) {
        int n = 1 + trial % MAXN;
        double a[MAXN + 1], b[MAXN + 1], ref[MAXN + 1];
        for (int j = 0; j <= MAXN; j++)
            a[j] = rnd();
        /* binomial_sums: the running sums, round by round */
        for (int j = 0; j <= MAXN; j++)
            b[j] = ref[j] = a[j];
        binomial_sums(b, n);
        for (int r = 1; r <= n; r++)
            for (int j = n; j >= r; j--)
                ref[j] += ref[j - 1];
        for (int j = 0; j <= n; j++)
            CHECK(memcmp(&b[j], &ref[j], sizeof(double)) == 0, "binomial_sums n=%d j=%d\n", n, j);
        /* halves: de Casteljau at 1/2, both edges of one triangle; the right
         * edge is also the left edge of the reversed coefficients' triangle
         * (how it was formed before), reversed */
        double w[MAXN + 1], left[MAXN + 1], right[MAXN + 1], l2[MAXN + 1], r2[MAXN + 1],
            rev[MAXN + 1], mirror[MAXN + 1];
        for (int j = 0; j <= n; j++) {
            w[j] = a[j];
            rev[j] = a[n - j];
        }
        left[0] = w[0];
        right[n] = w[n];
        mirror[n] = rev[0];
        for (int k = 1; k <= n; k++) {
            for (int j = 0; j <= n - k; j++) {
                w[j] = (w[j] + w[j + 1]) * 0.5;
                rev[j] = (rev[j] + rev[j + 1]) * 0.5;
            }
            left[k] = w[0];
            right[n - k] = w[n - k];
            mirror[n - k] = rev[0];
        }
        halves(a, n, l2, r2);
        for (int j = 0; j <= n; j++) {
            CHECK(memcmp(&l2[j], &left[j], sizeof(double)) == 0, "halves left n=%d j=%d\n", n, j);
            CHECK(memcmp(&r2[j], &right[j], sizeof(double)) == 0, "halves right n=%d j=%d\n", n, j);
            CHECK(memcmp(&mirror[j], &right[j], sizeof(double)) == 0, "mirror n=%d j=%d\n", n, j);
        }
        /* split_at: de Casteljau at t, each entry within 4 n u M of the same
         * triangle in long double (64-bit mantissa: its own error is 2^-11 of
         * that), M the largest |a_j|, as bernstein_clear's bound takes it */
        {
            (void)rnd(); /* (a fresh state: t uniform in bernstein_clear's (1/16, 15/16)) */
            double t = 0.0625 + 0.875 * ((double)(state >> 11) / 9007199254740992.0), M = 0;
            long double lw[MAXN + 1], ll[MAXN + 1], lr[MAXN + 1];
            for (int j = 0; j <= n; j++) {
                lw[j] = a[j];
                M = fabs(a[j]) > M ? fabs(a[j]) : M;
            }
            ll[0] = lw[0];
            lr[n] = lw[n];
            for (int k = 1; k <= n; k++) {
                for (int j = 0; j <= n - k; j++)
                    lw[j] = lw[j] + (long double)t * (lw[j + 1] - lw[j]);
                ll[k] = lw[0];
                lr[n - k] = lw[n - k];
            }
            split_at(a, n, t, l2, r2);
            double bound = 4.0 * n * UNIT_ROUNDOFF * M + DBL_MIN;
            for (int j = 0; j <= n; j++)
                CHECK(fabsl(l2[j] - ll[j]) <= bound && fabsl(r2[j] - lr[j]) <= bound,
                      "split_at n=%d j=%d t=%a: %Lg %Lg beyond %g\n", n, j, t,
                      fabsl(l2[j] - ll[j]), fabsl(r2[j] - lr[j]), bound);
        }
        /* compensated_with_slope: horner_compensated's value, bit for bit, and
         * the slope of plain Horner on D (the two chains share one loop) */
        {
            double xs = ldexp(1 + fabs(rnd()), (int)(trial % 7) - 3), slope = 0;
            double v0 = horner_compensated(a, n, xs);
            double v1 = compensated_with_slope(a, b, n, xs, &slope);
            double d = b[n - 1];
            for (int j = n - 2; j >= 0; j--)
                d = d * xs + b[j];
            CHECK(memcmp(&v0, &v1, sizeof v0) == 0 && memcmp(&slope, &d, sizeof d) == 0,
                  "compensated_with_slope n=%d\n", n);
        }
        /* speculate_first_root's first step reads p, p' and p''/2 at 0 off the
         * coefficients: what its three Horner chains give there (values; a zero's
         * sign aside) */
        if (n >= 2) {
            double f = a[n], d1 = 0, d2 = 0, x0 = 0;
            for (int i = n - 1; i >= 0; i--) {
                d2 = d2 * x0 + d1;
                d1 = d1 * x0 + f;
                f = f * x0 + a[i];
            }
            CHECK(f == a[0] && d1 == a[1] && d2 == a[2], "Laguerre at 0 n=%d\n", n);
        }
        /* point_at: the Taylor shift of p and |p| at x > 0 */
        double p[MAXN + 1];
        for (int j = 0; j <= n; j++)
            p[j] = a[j];
        if (p[n] == 0)
            p[n] = 0.75;
        Taylor tb;
        taylor_table(p, n, 0, 0, &tb);
        double x = ldexp(1 + fabs(rnd()), (int)(state % 9) - 4);
        double ta[MAXN + 1] = {0}, sa[MAXN + 1] = {0};
        for (int d = n; d >= 0; d--)
            for (int k = 0; k <= n - d; k++) {
                ta[k] = ta[k] * x + tb.tk[k][d];
                sa[k] = sa[k] * x + tb.ta[k][d];
            }
        Point pt;
        if (point_at(&tb, n, x, &pt))
            for (int k = 0; k <= n; k++)
                CHECK(memcmp(&pt.pt[k], &ta[k], sizeof(double)) == 0, "point_at n=%d k=%d\n", n, k);
        /* root_bound_exponent: 1 + max ceil((e_i + 1 - e_n) / (n - i)) over nonzero c_i */
        int e[MAXN + 1], nz[MAXN + 1];
        double cp[MAXN + 1];
        /* with zeros of both signs among the coefficients: the scan skips them */
        if (state % 3 == 0)
            p[state % (unsigned)n] = state % 2 ? -0.0 : 0.0;
        Scan sc = load_coefficients(p, n, cp, e, nz);
        if (!sc.finite) {
            CHECK(0, "load_coefficients refused finite data\n");
            continue;
        }
        /* the scan: extreme exponents of the nonzero ones, sign changes */
        int hi = INT_MIN, lo = INT_MAX, changes = 0, last = 0;
        for (int i = 0; i <= n; i++) {
            if (p[i] == 0)
                continue;
            hi = ilogb(p[i]) > hi ? ilogb(p[i]) : hi;
            lo = ilogb(p[i]) < lo ? ilogb(p[i]) : lo;
            int s = p[i] > 0 ? 1 : -1;
            changes += last != 0 && s != last;
            last = s;
        }
        CHECK(sc.emax == hi && sc.emin == lo && sc.changes == changes,
              "load_coefficients scan n=%d: %d %d %d, want %d %d %d\n", n, sc.emax,
              sc.emin, sc.changes, hi, lo, changes);
        /* the copy and the exponents, whichever of its loops ran (no zero among them:
         * the loop for normal numbers; else load_any) */
        for (int i = 0; i <= n; i++)
            CHECK(memcmp(&cp[i], &p[i], sizeof(double)) == 0 && nz[i] == (p[i] != 0) &&
                      e[i] == (p[i] != 0 ? ilogb(p[i]) : 0),
                  "load_coefficients n=%d i=%d: e %d nz %d\n", n, i, e[i], nz[i]);
        /* ... and with the coefficients, over the c_i of the sign opposite to
         * c_n's only (Kioustelidis: the positive roots) */
        for (int only = 0; only <= 1; only++) {
            int want = INT_MIN;
            for (int i = 0; i < n; i++) {
                if (p[i] == 0 || (only && (p[i] < 0) == (p[n] < 0)))
                    continue;
                int num = ilogb(p[i]) + 1 - ilogb(p[n]), den = n - i;
                int q = num >= 0 ? (num + den - 1) / den : -((-num) / den);
                want = q > want ? q : want;
            }
            want = want == INT_MIN ? INT_MIN : want + 1;
            CHECK(root_bound_exponent(e, nz, only ? cp : NULL, n) == want,
                  "root_bound_exponent n=%d only=%d\n", n, only);
        }
    }
    /* load_coefficients: an infinity or a NaN anywhere is refused */
    double c[3] = {1, 2, 3}, out[3];
    int e[3], nz[3];
    c[1] = INFINITY;
    CHECK(!load_coefficients(c, 2, out, e, nz).finite, "infinity accepted\n");
    c[1] = NAN;
    CHECK(!load_coefficients(c, 2, out, e, nz).finite, "NaN accepted\n");
    c[1] = 0x1p-1070; /* subnormal */
    Scan sc = load_coefficients(c, 2, out, e, nz);
    CHECK(sc.finite && e[1] == -1070 && nz[1] && sc.emin == -1070, "subnormal exponent\n");
    /* the extremes of the normal range take the loop for normal numbers, and stay finite */
    c[0] = DBL_MIN;
    c[1] = -DBL_MAX;
    c[2] = DBL_TRUE_MIN;
    sc = load_coefficients(c, 1, out, e, nz);
    CHECK(sc.finite && sc.emin == -1022 && sc.emax == 1023 && sc.changes == 1,
          "normal extremes: %d %d %d %d\n", sc.finite, sc.emin, sc.emax, sc.changes);
    sc = load_coefficients(c, 2, out, e, nz);
    CHECK(sc.finite && sc.emin == -1074 && sc.emax == 1023 && sc.changes == 2 && e[2] == -1074,
          "smallest subnormal: %d %d %d %d\n", sc.finite, sc.emin, sc.emax, sc.changes);
    printf("%d differences\n", bad);
    return bad != 0;
}
"""


def test_kernels_match_their_definitions(tmp_path: Path) -> None:
    run_c_program(PROGRAM, tmp_path, "kernels")
