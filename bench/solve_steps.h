/* What the kernel harnesses (roots_kernels.c, near_window.c) share: the runtime's steps before
 * its guess, replicated from solve() so that a kernel can be timed from the point where the
 * solver would start it.  Static, for one translation unit each; include after
 * max2code_roots.c (the steps are its static functions). */
#ifndef BENCH_SOLVE_STEPS_H
#define BENCH_SOLVE_STEPS_H

/* solve()'s steps before the guess, for the default method (graze check, no skin): the
 * checks of the input, the preparation and the tests at 0.  Returns the degree left, with the
 * normalised coefficients in c, the window in *T and the point 0 in *a; 0 when one of those
 * steps settles the solve (or hands it elsewhere). */
static int prepare_window(const double src[], int degree, double tmax, double c[], double *T,
                          Point *a)
{
    int e[MAXN + 1], nz[MAXN + 1];
    double t;
    if (!input_is_valid(src, degree, tmax, &t))
        return 0;
    Scan sc = load_coefficients(src, degree, c, e, nz);
    if (!sc.finite || degree < 3 || (sc.changes == 0 && c[0] != 0))
        return 0;
    int cleared = -1;
    if (tmax < INFINITY && c[0] != 0) {
        cleared = cleared_at_once(c, e, nz, degree, tmax, sc);
        if (cleared > 0)
            return 0;
    }
    double failed_w = cleared == 0 ? tmax : 0;
    double bound = -1; /* (reduce's positive-root bound, when it computed one) */
    int n = cleared == 0 ? degree : reduce(c, e, nz, degree, &tmax, 0, sc.emax, &bound);
    int emax = sc.emax;
    if (n < 3 || (n == degree ? sc.emax - sc.emin : spread(e, nz, n, &emax)) > MAX_SPREAD)
        return 0;
    normalise(c, n, emax, c[0] < 0 ? -1 : 1);
    double B = bound >= 0 ? bound : root_bound(e, nz, c, n);
    *T = tmax < B ? tmax : B;
    if (!(*T > 0 && *T <= (n <= 8 ? FAST_LIMIT_LOW : FAST_LIMIT_HIGH)))
        return 0;
    point_at_zero(c, n, noise_factor(n), 0, a);
    if (!(a->qt[0] - a->tol[0] > 0) || a->vq == 0 ||
        (*T != failed_w && clearly_positive(a, n, *T, 1)))
        return 0;
    return n;
}

#endif
