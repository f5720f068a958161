/*
 * exact_sign_driver.c -- the C runtime's exact_sign (roots/never_late.inc) on given
 * polynomials, for tests/runtime/test_exact_sign.py.  Includes runtime/c/max2code_roots.c to
 * reach its static functions.
 *
 * Each input line:   N M X C0 .. CN T0 .. T(M-1)   (X and the coefficients as hex floats)
 * Each output line:  exact_sign(c, N, t, M, X): 1, -1, 0 (p(X) = 0 exactly) or 2 (its a priori
 * test refused).
 */
#include "max2code_roots.c"

#include <stdio.h>

int main(void)
{
    int n, m;
    double x, c[MAXN + 1], t[MAXN + 1];
    while (scanf("%d %d %la", &n, &m, &x) == 3) {
        if (n < 0 || m < 0 || n + m > MAXN)
            return 1;
        for (int i = 0; i <= n; i++)
            if (scanf("%la", &c[i]) != 1)
                return 1;
        for (int j = 0; j < m; j++)
            if (scanf("%la", &t[j]) != 1)
                return 1;
        printf("%d\n", exact_sign(c, n, t, m, x));
    }
    return 0;
}
