/*
 * near_window.c -- what certifying "no root in the window" costs when complex roots lie close
 * to it, at best: the runtime's own certificate (Bernstein coefficients of the envelope q on
 * the window, split by de Casteljau until every piece is positive) with the places to split
 * handed to it for free.  Issue 10 asks for such windows in 6 degree-8 Horner evaluations;
 * this prices the runtime's certificate in its cheapest form, so that the target can be
 * judged against it (bench/near_window.py says more).
 *
 * The runtime's source is included (its kernels are static): build with -I runtime/c.  Input
 * on stdin, two lines a polynomial: FAMILY TMAX DEGREE C0 .. CN (hex floats, as
 * bench/roots_ab.c's), then "dips K D1 .. DK": the minima of p in the window, ascending,
 * found by the caller in high precision (the oracle: the solver would have to find them).
 *
 * The oracle certificate: solve()'s steps before the guess (prepare_window), the Bernstein
 * test on the whole window (bernstein_test), then a split at each minimum in turn (split_at,
 * with the runtime's error bound for it), each piece left of a minimum and the last one
 * cleared by its signs or by bernstein_clear's halvings; a piece that its split coefficients
 * do not settle (their error bound, carried from the whole window's, can exceed them near a
 * deep minimum) is tested afresh from Taylor points, as the runtime's counts would
 * (fresh_clear).  No guess, no search for the minima.  Timed with and without the
 * preparation before it.  Kept: the windows that reach the whole-window test with an even
 * count and that the oracle clears.
 *
 * Timing: each call on its own (bench/timing.h's clock, the empty region's cost subtracted),
 * the windows in an order shuffled anew each sweep and the kernels one after another on each
 * window in a rotating order, as bench/roots_harness.c times its methods; the unit is its
 * degree-8 Horner evaluation (timing.h's unit_region_ns).  Per kernel and window the median
 * over the sweeps; then the median and the mean over the windows.
 *
 * Output: a markdown table on stdout.  Argument 1: sweeps (default 15); argument "check":
 * prints "ok KEPT of REACHED of TOTAL SPLITS FRESH HALVED" -- KEPT windows cleared by the
 * oracle certificate, of REACHED that reach the whole-window test with an even count; SPLITS
 * at minima, FRESH tests from Taylor points, HALVED windows where a piece needed halvings --
 * when for every kept window the public solve finds no root and its negative control (a root
 * made at its deepest minimum: control_holds) is refused by the oracle and has a root by the
 * solve; else "differ" and the first window where that fails (tests/test_bench_kernels.py).
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "max2code_roots.c"
#include "timing.h"
#include "solve_steps.h"

#define MAXPOLY 4096
/* Bisection depth of the fresh tests (below). */
#define FRESH_DEPTH 8

typedef struct {
    double tmax, c[MAXN + 1]; /* as given */
    int degree;
    int ndips;
    double dips[MAXN]; /* minima of p in the window, ascending */
    double p[MAXN + 1], T; /* prepared: normalised, p[0] > 0, and the window */
} Near;

static Near kept[MAXPOLY];

/* Is q > 0 on the piece with Bernstein coefficients b (error bound err)?  bernstein_clear,
 * whose first look is this same test of the signs: repeated here only to tell whether the
 * piece needed its halvings (*halved). */
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
    *halved = 1;
    return bernstein_clear(&piece, n, 0);
}

/* A piece (x0, x1) that its split coefficients could not clear (their error bound, carried
 * from the whole window's, can exceed them near a deep minimum), tested afresh as the
 * runtime's counts test an interval: a Taylor point inside -- at the middle, since at a
 * minimum p' vanishes and point_at refuses a point where a Taylor coefficient's sign is not
 * certain -- with the bounds of clearly_positive towards both ends, the Bernstein test (and
 * its halvings) towards the right; failing those, both halves the same way, down to
 * FRESH_DEPTH.  The Taylor table is made once a solve, on first need. */
static int fresh_clear(const double p[], int n, Taylor *tb, int *have_tb, double x0, double x1,
                       int depth, int *fresh)
{
    if (!*have_tb) {
        taylor_table(p, n, noise_factor(n), 0, tb);
        *have_tb = 1;
    }
    ++*fresh;
    double m = 0.5 * (x0 + x1);
    Point pt;
    BernQ qb;
    double pT = 0;
    if (point_at(tb, n, m, &pt) && pt.qt[0] - pt.tol[0] > 0 &&
        clearly_positive(&pt, n, m - x0, -1)) {
        if (clearly_positive(&pt, n, x1 - m, 1))
            return 1;
        int bt = bernstein_test(&pt, n, x1 - m, &pT, &qb);
        if (bt == BERN_CLEAR || (bt == BERN_UNKNOWN && qb.even && bernstein_clear(&qb, n, 0)))
            return 1;
    }
    return depth < FRESH_DEPTH && fresh_clear(p, n, tb, have_tb, x0, m, depth + 1, fresh) &&
           fresh_clear(p, n, tb, have_tb, m, x1, depth + 1, fresh);
}

/* The certificate of k's prepared window (p, n, T, and the point 0 in *a) with its minima
 * given: the Bernstein test on the whole window, then a split at each minimum in turn (the
 * runtime's split_at and its error bound, split_rounding), each piece cleared by its signs, by
 * bernstein_clear's halvings or afresh (fresh_clear).  1 when it clears the window, 0 when
 * not, -1 when the whole-window test does not leave an even count (a root: not this family's
 * case).  *splits counts the splits at minima, *fresh the fresh tests, *halved whether a
 * piece needed halvings. */
static ALWAYS_INLINE int certificate(const Near *k, const double p[], int n, double T,
                                     const Point *a, int *splits, int *fresh, int *halved)
{
    BernQ qb;
    Taylor tb;
    int have_tb = 0;
    double pT = 0;
    *splits = *fresh = *halved = 0;
    int bt = bernstein_test(a, n, T, &pT, &qb);
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
        double left[MAXN + 1], right[MAXN + 1];
        left[0] = right[0] = 0; /* (gcc -Wmaybe-uninitialized cannot see n >= 1) */
        if (i < k->ndips) {
            double M = 0;
            for (int j = 0; j <= n; j++)
                M = fabs(cur[j]) > M ? fabs(cur[j]) : M;
            split_at(cur, n, t, left, right);
            err += split_rounding(1, n, M) + DBL_MIN; /* bernstein_clear's bound */
            ++*splits;
        } else {
            for (int j = 0; j <= n; j++)
                left[j] = cur[j];
        }
        if (!piece_clear(left, err, n, halved) &&
            !fresh_clear(p, n, &tb, &have_tb, lo * T, d * T, 0, fresh))
            return 0;
        for (int j = 0; j <= n; j++)
            cur[j] = right[j];
        lo = d;
    }
    return 1;
}

/* The oracle certificate from the input: solve()'s steps before the guess (prepare_window),
 * then certificate(); -1 too where the preparation settles the window, drops terms or cuts
 * the window at its bound on the roots (not this family's case: the exact counts of
 * bench/near_window.py are for [0, tmax]). */
static ALWAYS_INLINE int oracle_clear(const Near *k, int degree, int *splits, int *fresh,
                                      int *halved)
{
    double p[MAXN + 1], T = 0;
    Point a;
    if (prepare_window(k->c, degree, k->tmax, p, &T, &a) != degree || T != k->tmax)
        return -1;
    return certificate(k, p, degree, T, &a, splits, fresh, halved);
}

enum { UNIT, SOLVE, PREPARATION, WINDOW_TEST, ORACLE, CERTIFICATE, NKERNELS };
static const char *NAMES[NKERNELS] = {
    "one degree-8 Horner evaluation (the unit)",
    "the runtime's solve today (m2c_first_root_ex)",
    "before any test of the window: validation, the preparation, the tests at 0",
    "those, and the Bernstein test on the whole window",
    "those, and the splits at the minima, given for free (the oracle certificate)",
    "the certificate alone, from prepared coefficients: the point 0, the whole-window test, the splits"};

/* One call of kernel `which` (not SOLVE) on k, for k's degree as a constant (below); its
 * result, so that the call cannot be dropped. */
static ALWAYS_INLINE double kernel_core(int which, const Near *k, int degree)
{
    double c[MAXN + 1] = {0}, T = 0, pT = 0;
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
    case ORACLE:
        return oracle_clear(k, degree, &splits, &fresh, &halved);
    default:
        point_at_zero(k->p, degree, noise_factor(degree), 0, &a);
        return certificate(k, k->p, degree, k->T, &a, &splits, &fresh, &halved);
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

/* The negative control of a kept window: k with its constant term moved by 1.5 times p's
 * value at its deepest minimum, towards 0, so that p crosses 0 there (two roots in the
 * window).  The oracle must not clear it, and the solve must find a root: else the check
 * below proves nothing (an oracle that clears everything would pass on this family alone). */
static int control_holds(const Near *k, int *status)
{
    Near ctl = *k;
    double deepest = INFINITY;
    for (int i = 0; i < k->ndips; i++) {
        double v = horner(k->c, k->degree, k->dips[i], 0, 0);
        deepest = fabs(v) < fabs(deepest) ? v : deepest;
    }
    if (!(fabs(deepest) < INFINITY))
        return 0;
    ctl.c[0] -= 1.5 * deepest;
    int splits, fresh, halved;
    double t = 0;
    int g = 0;
    *status = m2c_first_root_ex(ctl.c, ctl.degree, ctl.tmax, &t, M2C_METHOD_INTERVAL, &g);
    return *status == 1 && oracle_clear(&ctl, ctl.degree, &splits, &fresh, &halved) != 1;
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
            continue; /* not cleared by the oracle's tests */
        double t = 0;
        int g = 0, status = 0;
        if (m2c_first_root_ex(k->c, k->degree, k->tmax, &t, M2C_METHOD_INTERVAL, &g) != 0) {
            /* the oracle cleared a window where the solver finds a root: one of them is wrong */
            printf("differ %d: the oracle certificate clears it, the solve finds %a\n", total, t);
            return 1;
        }
        if (!control_holds(k, &status)) {
            printf("differ %d: its negative control (a root at its deepest minimum) is cleared "
                   "by the oracle or not found by the solve (status %d)\n", total, status);
            return 1;
        }
        Point a;
        prepare_window(k->c, k->degree, k->tmax, k->p, &k->T, &a);
        splits_all += splits;
        fresh_all += fresh;
        halved_all += halved;
        m++;
    }
    if (m == 0) {
        fprintf(stderr, "near_window: the oracle clears none of the %d windows\n", total);
        return 2;
    }
    if (check) {
        printf("ok %d of %d of %d %d %d %d\n", m, reached, total, splits_all, fresh_all, halved_all);
        return 0;
    }
    double overhead = empty_region_ns();
    double *ns = malloc((size_t)m * NKERNELS * (size_t)sweeps * sizeof *ns);
    size_t *order = malloc((size_t)m * sizeof *order);
    double (*c8)[9] = calloc((size_t)m, sizeof *c8);
    double *x8 = malloc((size_t)m * sizeof *x8);
    if (ns == NULL || order == NULL || c8 == NULL || x8 == NULL)
        return 2;
    for (int i = 0; i < m; i++) {
        order[i] = (size_t)i;
        for (int j = 0; j <= kept[i].degree && j <= 8; j++)
            c8[i][j] = kept[i].c[j];
        x8[i] = 0.5 * kept[i].tmax;
    }
    for (int sw = 0; sw < sweeps; sw++) {
        shuffle(order, (size_t)m);
        for (int o = 0; o < m; o++) {
            size_t i = order[o];
            for (int jj = 0; jj < NKERNELS; jj++) {
                int which = (jj + o + sw) % NKERNELS; /* the order rotates */
                double *slot = &ns[(i * NKERNELS + (size_t)which) * (size_t)sweeps + (size_t)sw];
                if (which == UNIT) {
                    *slot = unit_region_ns((const double (*)[9])c8, x8, (size_t)m, i, overhead);
                } else {
                    double t0 = now_ns();
                    double v = kernel(which, &kept[i]);
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
           "splits at minima a window, %.2f fresh tests a window; halvings needed in %d "
           "windows.\n\n",
           reached, total, m, unit, sweeps, (double)splits_all / m, (double)fresh_all / m,
           halved_all);
    printf("| kernel | ns per call (median) | evaluations (median) | evaluations (mean) |\n"
           "|---|---:|---:|---:|\n");
    for (int j = 1; j < NKERNELS; j++)
        printf("| %s | %.0f | %.1f | %.1f |\n", NAMES[j], med[j], med[j] / unit, mean[j] / unit);
    free(per);
    free(x8);
    free(c8);
    free(order);
    free(ns);
    return 0;
}
