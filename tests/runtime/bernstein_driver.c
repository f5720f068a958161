/*
 * bernstein_driver.c -- the C runtime's Bernstein kernels on given Points, for
 * tests/runtime/test_python_control_flow.py: their intermediate values, bit for bit, which
 * the solver's answers and counts only show where a last bit flips a decision.  Includes
 * runtime/c/max2code_roots.c to reach its static functions.
 *
 * Each input line:   N X W PT0 .. PTN QT0 .. QTN TOL0 .. TOLN   (hex floats)
 * Each output line (floats as %a):
 *   ANSWER PEND [Q0 .. QN ERR EVEN CLEARED] SPECULATED R TOUCH MADDS ANSWER2 PEND2
 * ANSWER, PEND: bernstein_test(pt, N, W) with qb (PEND NaN when p's coefficients are not
 * formed); the bracket only unless ANSWER is BERN_CLEAR (qb is not filled then): qb's
 * coefficients, bound and even flag, and bernstein_clear(qb) (whatever qb.even says), halving
 * only and with its first split at 0.3.
 * SPECULATED, R, TOUCH, MADDS: speculate_first_root on the polynomial PT with T = X + W, its
 * touch, and the multiply-adds it counts (3 N per Laguerre or Newton-on-p' step, N for the
 * rounding bound at a critical point: its number of steps).
 * ANSWER2, PEND2: bernstein_test without qb.  Built with -DM2C_COUNT for MADDS.
 */
#include "max2code_roots.c"

#include <stdio.h>
#include <stdlib.h>

static double next(char **p)
{
    char *end;
    double v = strtod(*p, &end);
    *p = end;
    return v;
}

int main(void)
{
    static char line[16384];
    while (fgets(line, sizeof line, stdin) != NULL) {
        char *p = line, *end;
        int n = (int)strtol(p, &end, 10);
        if (end == p || n < 1 || n > MAXN)
            continue;
        p = end;
        Point pt;
        memset(&pt, 0, sizeof pt);
        pt.x = next(&p);
        double w = next(&p);
        for (int k = 0; k <= n; k++)
            pt.pt[k] = next(&p);
        for (int k = 0; k <= n; k++)
            pt.qt[k] = next(&p);
        for (int k = 0; k <= n; k++)
            pt.tol[k] = next(&p);
        double pend = NAN;
        BernQ qb;
        int answer = bernstein_test(&pt, n, w, &pend, &qb);
        printf("%d %a", answer, pend);
        if (answer != BERN_CLEAR) {
            for (int j = 0; j <= n; j++)
                printf(" %a", qb.b[j]);
            printf(" %a %d %d %d", qb.err, qb.even != 0, bernstein_clear(&qb, n, 0),
                   bernstein_clear(&qb, n, 0.3)); /* halves only; the first split at 0.3 */
        }
        double r = 0, touch = 0, dip = 0, over = 0, before = m2c_count[2];
        int speculated = speculate_first_root(pt.pt, n, pt.x + w, &r, &touch, &dip, &over);
        double madds = m2c_count[2] - before;
        printf(" %d %a %a %a %a %.0f", speculated, speculated ? r : 0.0, touch, dip, over, madds);
        double pend2 = NAN;
        int answer2 = bernstein_test(&pt, n, w, &pend2, NULL);
        printf(" %d %a\n", answer2, pend2);
    }
    return 0;
}
