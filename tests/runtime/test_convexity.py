"""The derivative method's shortcut where p is convex (C convex_on).

Where p'' is certainly positive on the interval (beyond the rounding of its plain Horner
value anywhere there), the level of the roots of p'' is empty whatever the levels below it
find, so the roots of p' are found from an empty level without the recursion below it: the
same steps and the same bits (on the grazes, most calls: the small interval around a touch).
A program that includes max2code_roots.c checks, on polynomials with a double root and on
generic ones, over intervals from 2^-12 to 4 times the double root's size:

* soundness: where convex_on says yes, p'' evaluated plainly at 257 points of the interval
  (its ends among them) is positive at every one;
* the same critical points, bit for bit, as the full recursion (written out here as it was);
* the shortcut is taken often enough for the two checks to mean something, and refused often
  enough (intervals where p'' changes sign) for the first to.
"""
from __future__ import annotations

from pathlib import Path

from .c_program import run_c_program


PROGRAM = r"""
#include "max2code_roots.c"
#include <stdio.h>

static unsigned long long state = 0x2545F4914F6CDD1DULL;
static double uni(void) /* [0, 1) */
{
    state ^= state << 13; state ^= state >> 7; state ^= state << 17;
    return (double)(state >> 11) / 9007199254740992.0;
}

/* The recursion as critical_points runs it without the shortcut. */
static int full_recursion(double d[MAXN + 1][MAXN + 1], int n, double lo, double T, double crit[])
{
    double r[2], disc, level[MAXN];
    int nl = 0;
    if (quad_roots(d[2][2], d[2][1], d[2][0], r, &disc) == 2)
        for (int i = 0; i < 2; i++)
            if (r[i] > lo && r[i] < T && (nl == 0 || r[i] > level[nl - 1]))
                level[nl++] = r[i];
    for (int m = 3; m < n; m++) {
        double next[MAXN];
        double tol = m == n - 1 ? TOL_CRITICAL : TOL_LEVEL;
        nl = roots_in_pieces(d[m], d[m - 1], m, lo, level, nl, T, tol, 0, next);
        for (int i = 0; i < nl; i++)
            level[i] = next[i];
    }
    for (int i = 0; i < nl; i++)
        crit[i] = level[i];
    return nl;
}

int main(void)
{
    int bad = 0, convex = 0, refused = 0;
    for (int trial = 0; trial < 40000; trial++) {
        int n = 4 + trial % 13;
        /* a double root at s (or, every third trial, none), complex pairs near s, the
         * other roots real: beyond s or negative; leading coefficient 1 */
        double s = pow(10, 4 * uni() - 2), c[MAXN + 1] = {1};
        int deg = 0, dbl = trial % 3 != 0;
        int pairs = (int)(uni() * ((n - 2 * dbl) / 2 + 1));
        for (int k = 0; k < pairs; k++) { /* times x^2 - 2 a x + (a^2 + b^2) */
            double re = s * (4 * uni() - 1), im = s * (0.05 + 2 * uni());
            double q[3] = {re * re + im * im, -2 * re, 1}, out[MAXN + 1] = {0};
            for (int i = 0; i <= deg; i++)
                for (int j = 0; j < 3; j++)
                    out[i + j] += c[i] * q[j];
            deg += 2;
            for (int i = 0; i <= deg; i++)
                c[i] = out[i];
        }
        for (int k = 0; deg < n; k++) { /* times x - r */
            double u = uni();
            double r = k < 2 * dbl ? s : u < 0.6 ? s * (1.2 + 10 * uni()) : -s * (0.1 + 10 * uni());
            double out[MAXN + 1] = {0};
            for (int i = 0; i <= deg; i++) {
                out[i + 1] += c[i];
                out[i] -= r * c[i];
            }
            deg++;
            for (int i = 0; i <= deg; i++)
                c[i] = out[i];
        }
        double d[MAXN + 1][MAXN + 1], a[MAXN], b[MAXN];
        derivative_chain(c, n, d);
        /* an interval around s, of relative width 2^-12 .. 4, or anywhere in [0, 4 s] */
        double w = s * ldexp(1.0, -(int)(14 * uni())) * (0.5 + uni());
        double lo = trial % 2 ? s - w * uni() : 4 * s * uni();
        double T = lo + w;
        if (!(lo >= 0))
            lo = 0;
        int cv = convex_on(d, n, lo, T);
        convex += cv;
        refused += !cv;
        if (cv) {
            for (int k = 0; k <= 256; k++) {
                double x = k == 256 ? T : lo + (T - lo) * (k / 256.0);
                double v = horner(d[n - 2], n - 2, x, 0, 0);
                if (!(v > 0)) {
                    bad++;
                    if (bad < 10)
                        printf("convex_on yes, but p''(%a) = %a (n=%d lo=%a T=%a)\n", x, v, n, lo, T);
                    break;
                }
            }
        }
        int na = critical_points(d, n, lo, T, 0, a), nb = full_recursion(d, n, lo, T, b);
        int same = na == nb;
        for (int i = 0; same && i < na; i++)
            same = memcmp(&a[i], &b[i], sizeof(double)) == 0;
        if (!same) {
            bad++;
            if (bad < 10)
                printf("critical points differ (n=%d lo=%a T=%a): %d vs %d\n", n, lo, T, na, nb);
        }
    }
    printf("%d convex, %d refused, %d differences\n", convex, refused, bad);
    return bad != 0 || convex < 2000 || refused < 2000;
}
"""


def test_convex_shortcut_is_sound_and_changes_nothing(tmp_path: Path) -> None:
    run_c_program(PROGRAM, tmp_path, "convexity")
