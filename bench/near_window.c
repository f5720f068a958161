/*
 * near_window.c -- what certifying "no root in the window" costs when complex roots lie close
 * to it, at best: the runtime's own certificate (Bernstein coefficients of the envelope q on
 * the window, split by de Casteljau until every piece is positive) with the places to split
 * handed to it for free.  Issue 10 asks for such windows in 6 degree-8 Horner evaluations;
 * this prices the cheapest subdivision certificate there is, so that the target can be judged
 * against it (bench/near_window.py says more).
 *
 * The runtime's source is included (its kernels are static): build with -I runtime/c.  Input
 * on stdin, two lines a polynomial: FAMILY TMAX DEGREE C0 .. CN (hex floats, as
 * bench/roots_ab.c's), then "dips K D1 .. DK": the minima of p in the window, ascending,
 * found by the caller in high precision (the oracle: the solver would have to find them).
 *
 * The oracle certificate: solve()'s steps before the guess (prepare_window), the Bernstein
 * test on the whole window (bernstein_test), then a split at each dip in turn (split_at, the
 * runtime's error bound for it), each piece left of a dip and the last one cleared by
 * bernstein_clear -- at once when its coefficients are positive, else by its halvings.  No
 * guess: what is left of the runtime's path for these windows when the dips are known; a
 * piece whose split coefficients do not settle it (their error bound, carried
 * from the whole window's, can exceed them near a deep minimum) is tested afresh from a Taylor
 * point, as the runtime's counts would.  Kept: the windows that reach the whole-window test
 * with an even count and that this certificate clears.
 *
 * Timing: each call on its own (bench/timing.h's clock, the empty region's cost subtracted),
 * the windows in an order shuffled anew each sweep and the kernels in a rotating order, as
 * bench/roots_harness.c times solves; the unit is its degree-8 Horner evaluation (HORNER_BATCH
 * of them a timed region, each waiting for the last).  Per kernel and window the median over
 * the sweeps; then the median and the mean over the windows.
 *
 * Output: a markdown table on stdout.  Argument 1: sweeps (default 15); argument "check":
 * prints "ok KEPT of REACHED of TOTAL SPLITS FRESH HALVED" -- KEPT windows cleared by the
 * oracle certificate, none of them with a root by the public solve, of REACHED that reach the
 * whole-window test with an even count (the rest of REACHED: a minimum within the envelope's
 * rounding noise, the derivative method's case); SPLITS at minima, FRESH pieces tested from a
 * Taylor point, HALVED windows where a piece needed halvings -- or the first window where
 * the oracle and the solve disagree (tests/test_bench_kernels.py).
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "max2code_roots.c"
#include "timing.h"
#include "solve_steps.h"

#define MAXPOLY 4096
#define HORNER_BATCH 16

typedef struct {
    double tmax, c[MAXN + 1]; /* as given */
    int degree;
    int ndips;
    double dips[MAXN]; /* minima of p in the window, ascending */
} Near;

static Near kept[MAXPOLY];

/* Is q > 0 on the piece with Bernstein coefficients b (error bound err)?  At once when they
 * are all above the bound; else bernstein_clear's halvings (*halved set). */
static int piece_clear(const double b[], double err, int n, int *halved)
{
    double lo = b[0];
    for (int j = 1; j <= n; j++)
        lo = b[j] < lo ? b[j] : lo;
    if (lo > err)
        return 1;
    BernQ piece;
    for (int j = 0; j <= n; j++)
        piece.b[j] = b[j];
    piece.err = err;
    piece.even = 1;
    *halved = 1;
    return bernstein_clear(&piece, n, 0);
}

/* A piece [x, x + w] of the window that its split coefficients could not clear (their error
 * bound, carried from the whole window's, is above the coefficients near a deep minimum):
 * tested afresh, as the runtime's Taylor points do -- q's Taylor coefficients at x
 * (point_at), their Bernstein test on [x, x + w], its halvings where that does not settle it.
 * The Taylor table is made once a solve, on first need. */
static int fresh_clear(const double c[], int n, Taylor *tb, int *have_tb, double x, double w)
{
    if (!*have_tb) {
        taylor_table(c, n, noise_factor(n), 0, tb);
        *have_tb = 1;
    }
    Point pt;
    BernQ qb;
    double pT = 0;
    if (!point_at(tb, n, x, &pt) || !(pt.qt[0] - pt.tol[0] > 0))
        return 0;
    int bt = bernstein_test(&pt, n, w, &pT, &qb);
    return bt == BERN_CLEAR || (bt == BERN_UNKNOWN && qb.even && bernstein_clear(&qb, n, 0));
}

/* The oracle certificate of k's window (see the header): 1 when it clears it, 0 when not,
 * -1 when the polynomial does not reach the whole-window test with an even count.  *splits
 * counts the splits at dips, *fresh the pieces tested afresh, *halved whether a piece needed
 * halvings. */
static ALWAYS_INLINE int oracle_clear(const Near *k, int degree, int *splits, int *fresh,
                                      int *halved)
{
    double c[MAXN + 1], T = 0, pT = 0;
    Point a;
    BernQ qb;
    Taylor tb;
    int have_tb = 0;
    *splits = *fresh = *halved = 0;
    if (prepare_window(k->c, degree, k->tmax, c, &T, &a) != degree)
        return -1; /* (settled, or terms dropped: not this family's case) */
    int n = degree;
    int bt = bernstein_test(&a, n, T, &pT, &qb);
    if (bt == BERN_CLEAR)
        return 1;
    if (bt == BERN_ONE || !qb.even)
        return -1;
    double cur[MAXN + 1], err = qb.err, lo = 0;
    for (int j = 0; j <= n; j++)
        cur[j] = qb.b[j];
    for (int i = 0; i <= k->ndips; i++) {
        double d = i < k->ndips ? k->dips[i] / T : 1;
        double t = (d - lo) / (1 - lo);
        if (i < k->ndips && !(t > 0 && t < 1))
            continue;
        double left[MAXN + 1], right[MAXN + 1], M = 0;
        left[0] = right[0] = 0; /* (gcc -Wmaybe-uninitialized cannot see n >= 1) */
        if (i < k->ndips) {
            for (int j = 0; j <= n; j++)
                M = fabs(cur[j]) > M ? fabs(cur[j]) : M;
            split_at(cur, n, t, left, right);
            err += 8 * n * UNIT_ROUNDOFF * M + DBL_MIN; /* bernstein_clear's bound for a split */
            ++*splits;
        } else {
            for (int j = 0; j <= n; j++)
                left[j] = cur[j];
        }
        if (!piece_clear(left, err, n, halved)) {
            ++*fresh;
            if (!fresh_clear(c, n, &tb, &have_tb, lo * T, (d - lo) * T))
                return 0;
        }
        for (int j = 0; j <= n; j++)
            cur[j] = right[j];
        lo = d;
    }
    return 1;
}

enum { UNIT, SOLVE, PREPARATION, WINDOW_TEST, ORACLE, NKERNELS };
static const char *NAMES[NKERNELS] = {
    "one degree-8 Horner evaluation (the unit)",
    "the runtime's solve today (m2c_first_root_ex)",
    "before any test of the window: validation, the preparation, the tests at 0",
    "those, and the Bernstein test on the whole window",
    "those, and the splits at the dips, given for free (the oracle certificate)"};

/* One call of kernel `which` (not SOLVE) on k, for k's degree as a constant (below); its
 * result, so that the call cannot be dropped. */
static ALWAYS_INLINE double kernel_core(int which, const Near *k, int degree)
{
    double c[MAXN + 1], T = 0, pT = 0;
    Point a;
    BernQ qb;
    int splits, fresh, halved;
    switch (which) {
    case PREPARATION:
        return prepare_window(k->c, degree, k->tmax, c, &T, &a) + c[0] + T;
    case WINDOW_TEST:
        if (prepare_window(k->c, degree, k->tmax, c, &T, &a) != degree)
            return -1;
        return bernstein_test(&a, degree, T, &pT, &qb) + qb.b[0];
    default:
        return oracle_clear(k, degree, &splits, &fresh, &halved);
    }
}

/* The kernels for degree 8 with the degree a constant, every call below inlined: as the
 * runtime's own copies for degree 8 (first_root_interval_8, solve_8), so that the oracle is
 * priced as the runtime would run it. */
NOINLINE __attribute__((flatten)) static double kernel_8(int which, const Near *k)
{
    return kernel_core(which, k, 8);
}

NOINLINE static double kernel_any(int which, const Near *k)
{
    return kernel_core(which, k, k->degree);
}

static double kernel(int which, const Near *k)
{
    if (which == SOLVE) {
        double t = 0;
        int g = 0;
        return m2c_first_root_ex(k->c, k->degree, k->tmax, &t, M2C_METHOD_INTERVAL, &g);
    }
    return k->degree == 8 ? kernel_8(which, k) : kernel_any(which, k);
}

/* "dips K D1 .. DK" into k; 0 when the line is not that. */
static int read_dips(const char *line, Near *k)
{
    const char *s = line;
    char *e;
    if (strncmp(s, "dips ", 5) != 0)
        return 0;
    s += 5;
    long nd = strtol(s, &e, 10);
    if (e == s || nd < 0 || nd > MAXN)
        return 0;
    s = e;
    for (int i = 0; i < nd; i++) {
        k->dips[i] = strtod(s, &e);
        if (e == s || (i > 0 && !(k->dips[i] > k->dips[i - 1])))
            return 0;
        s = e;
    }
    k->ndips = (int)nd;
    return 1;
}

int main(int argc, char **argv)
{
    int check = argc > 1 && strcmp(argv[1], "check") == 0;
    int sweeps = !check && argc > 1 ? atoi(argv[1]) : 15;
    if (sweeps < 1 || sweeps > 1001) {
        fprintf(stderr, "near_window: sweeps must be 1..1001\n");
        return 2;
    }
    char line[16384];
    int total = 0, reached = 0, m = 0, splits_all = 0, fresh_all = 0, halved_all = 0;
    while (fgets(line, sizeof line, stdin) && m < MAXPOLY) {
        Near *k = &kept[m];
        char fam[32];
        int got = read_poly_line(line, fam, &k->tmax, &k->degree, k->c, MAXN);
        if (got == 0)
            continue;
        if (got < 0 || !fgets(line, sizeof line, stdin) || !read_dips(line, k)) {
            fprintf(stderr, "near_window: bad input at polynomial %d\n", total + 1);
            return 2;
        }
        total++;
        int splits, fresh, halved;
        int r = oracle_clear(k, k->degree, &splits, &fresh, &halved);
        if (r < 0)
            continue;
        reached++;
        if (r == 0)
            continue; /* a minimum within the envelope's noise: the derivative method's case */
        double t = 0;
        int g = 0;
        if (m2c_first_root_ex(k->c, k->degree, k->tmax, &t, M2C_METHOD_INTERVAL, &g) != 0) {
            /* the oracle cleared a window where the solver finds a root: one of them is wrong */
            printf("differ %d: the oracle certificate clears it, the solve finds %a\n", total, t);
            return 1;
        }
        splits_all += splits;
        fresh_all += fresh;
        halved_all += halved;
        m++;
    }
    if (m == 0) {
        fprintf(stderr, "near_window: no polynomial of %d reaches the whole-window test\n", total);
        return 2;
    }
    if (check) {
        printf("ok %d of %d of %d %d %d %d\n", m, reached, total, splits_all, fresh_all, halved_all);
        return 0;
    }
    double overhead = empty_region_ns();
    double *ns = malloc((size_t)m * NKERNELS * (size_t)sweeps * sizeof *ns);
    int *order = malloc((size_t)m * sizeof *order);
    if (ns == NULL || order == NULL)
        return 2;
    for (int i = 0; i < m; i++)
        order[i] = i;
    for (int sw = 0; sw < sweeps; sw++) {
        for (int i = m; i > 1; i--) { /* Fisher-Yates */
            int j = (int)(xorshift() % (unsigned long long)i), tmp = order[i - 1];
            order[i - 1] = order[j];
            order[j] = tmp;
        }
        for (int o = 0; o < m; o++) {
            int i = order[o];
            const Near *k = &kept[i];
            for (int jj = 0; jj < NKERNELS; jj++) {
                int which = (jj + o + sw) % NKERNELS; /* the order rotates */
                double *slot = &ns[((size_t)i * NKERNELS + (size_t)which) * (size_t)sweeps + (size_t)sw];
                if (which == UNIT) {
                    /* HORNER_BATCH evaluations, each waiting for the last (roots_harness.c's unit) */
                    double v = 0, x = 0.5 * k->tmax, c8[9] = {0};
                    for (int j = 0; j <= k->degree && j <= 8; j++)
                        c8[j] = k->c[j];
                    double t0 = now_ns();
                    for (int h = 0; h < HORNER_BATCH; h++)
                        v = horner8(c8, x + v * 0.0);
                    double t1 = now_ns();
                    sink = v;
                    *slot = (t1 - t0 - overhead) / HORNER_BATCH;
                } else {
                    double t0 = now_ns();
                    double v = kernel(which, k);
                    double t1 = now_ns();
                    sink = v;
                    *slot = t1 - t0 - overhead;
                }
            }
        }
    }
    /* per kernel: the median over sweeps per window, then the median and the mean over windows */
    double *per = malloc((size_t)m * sizeof *per);
    double med[NKERNELS], mean[NKERNELS];
    if (per == NULL)
        return 2;
    for (int j = 0; j < NKERNELS; j++) {
        double sum = 0;
        for (int i = 0; i < m; i++) {
            per[i] = median(&ns[((size_t)i * NKERNELS + (size_t)j) * (size_t)sweeps], sweeps);
            sum += per[i];
        }
        mean[j] = sum / m;
        med[j] = median(per, m);
    }
    double unit = med[UNIT];
    printf("%d of %d windows reach the whole-window test with an even count, %d of them "
           "cleared by the oracle certificate (kept, timed); unit %.1f ns; %d sweeps; %.2f "
           "splits at minima a window, %.2f pieces a window tested afresh; halvings needed in "
           "%d windows.\n\n",
           reached, total, m, unit, sweeps, (double)splits_all / m, (double)fresh_all / m,
           halved_all);
    printf("| kernel | ns per call (median) | evaluations (median) | evaluations (mean) |\n"
           "|---|---:|---:|---:|\n");
    for (int j = 1; j < NKERNELS; j++)
        printf("| %s | %.0f | %.1f | %.1f |\n", NAMES[j], med[j], med[j] / unit, mean[j] / unit);
    free(per);
    free(order);
    free(ns);
    return 0;
}
