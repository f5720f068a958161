/*
 * roots_kernels.c -- where the time of a solve that the certified guess settles goes, kernel by
 * kernel, in units of one degree-8 Horner evaluation (bench/timing.h's unit): the guess
 * (Laguerre's method from 0), its certificate (one Bernstein test on (0, r (1 + 2^-20)], or
 * up to the end of a step that went past the root), the polish (one compensated Newton step,
 * usually; plain Newton first after such a step), and the whole solve; the preparation and the
 * early tests are what is left.  Issue 10 asks for a generic octic in 15 evaluations: this says
 * which parts a faster solver would have to shrink.
 *
 * The runtime's source is included (its kernels are static): build with -I runtime/c.  Input on
 * stdin as bench/roots_ab.c's (FAMILY TMAX DEGREE C0 .. CN, hex floats).  Each polynomial is
 * prepared as solve() prepares it (load, Descartes, step 0b, reduce, normalise, the bound on the
 * positive roots), and kept when its default solve is settled by the certified guess: the
 * window is in the fast range, the bounds at 0 do not clear it, the guess converges and the
 * certificate holds.  (The replica of solve()'s steps is checked: "check" mode compares the
 * polished root with the public m2c_first_root_ex's, bit for bit.)
 *
 * Timing: per kernel, regions of one call per kept polynomial, each call waiting for the last
 * one's result (a solve's kernels wait for each other too: the certificate needs the guess, the
 * polish its window), the kernels interleaved region by region with the unit; per kernel the
 * median over regions of the time per call, the empty region's cost subtracted.
 *
 * Then every polynomial of the input by the path its solve takes (settled before the guess,
 * the certified guess, a certificate that fails, a guess that fails): each path's whole solves
 * timed as the kernels, in regions of their own, and its share of the family's mean -- what a
 * faster certified path can gain at most, and what the solves it does not settle cost.
 *
 * Output: two markdown tables on stdout.  Argument 1: regions (default 201); argument "check":
 * prints "ok KEPT of TOTAL", or the first difference, or the paths' count of certified guesses
 * where it is not the number kept (tests/test_bench_kernels.py).
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "max2code_roots.c"
#include "timing.h"
#include "solve_steps.h"

#define MAXPOLY 4096

typedef struct {
    double tmax, c[MAXN + 1]; /* as given */
    int degree;
    double p[MAXN + 1]; /* normalised, p[0] > 0 */
    int n;
    double T, w, r; /* window, certificate window, guess (Newton's start) */
    double tol;     /* refine_root's: PRECISE_NOW after a converged guess, 0 after an overshot */
    Point a;        /* the point 0 */
    double dp[MAXN];
    double root; /* the public solve's answer */
} Kept;

static Kept kept[MAXPOLY];

/* Every polynomial of the input, and the path its default solve takes: what the mean of a
 * family is made of (the certified guess's share, and the solves it leaves to the Taylor
 * points and the bisection). */
enum { SETTLED_EARLY, CERTIFIED, CERTIFICATE_FAILS, GUESS_FAILS, NPATHS };
static const char *PATH_NAMES[NPATHS] = {
    "settled before the guess (the tests at 0, or handed elsewhere)",
    "the certified guess", "the guess converges, its certificate fails",
    "the guess fails (complex roots in the way, out of the window, no convergence)"};
typedef struct {
    double tmax, c[MAXN + 1];
    int degree, path;
} Input;
static Input inputs[MAXPOLY];
static int path_size[NPATHS];

static int path_of(const Input *in)
{
    double c[MAXN + 1], T, r, touch, dip = 0, pT, over = 0;
    Point a;
    int n = prepare_window(in->c, in->degree, in->tmax, c, &T, &a);
    if (n == 0)
        return SETTLED_EARLY;
    int guess = speculate_first_root(c, n, T, &r, &touch, &dip, &over);
    if (!guess)
        return GUESS_FAILS;
    double end = guess == OVERSHOT ? over : r, w = end + end * 0x1p-20;
    w = w < T ? w : T;
    return bernstein_test(&a, n, w, &pT, NULL) == BERN_ONE ? CERTIFIED : CERTIFICATE_FAILS;
}

/* 1 when the certified guess settles the solve of k (its default method). */
static int prepare(Kept *k)
{
    double c[MAXN + 1], T;
    int n = prepare_window(k->c, k->degree, k->tmax, c, &T, &k->a);
    if (n == 0)
        return 0;
    double r, touch, dip = 0, pT, over = 0;
    int guess = speculate_first_root(c, n, T, &r, &touch, &dip, &over);
    if (!guess)
        return 0;
    double end = guess == OVERSHOT ? over : r, w = end + end * 0x1p-20;
    w = w < T ? w : T;
    k->tol = guess == OVERSHOT ? 0 : PRECISE_NOW;
    if (bernstein_test(&k->a, n, w, &pT, NULL) != BERN_ONE)
        return 0;
    memcpy(k->p, c, sizeof c);
    k->n = n;
    k->T = T;
    k->w = w;
    k->r = r;
    derivative(c, n, k->dp);
    int g = 0;
    if (m2c_first_root_ex(k->c, k->degree, k->tmax, &k->root, M2C_METHOD_INTERVAL, &g) != 1)
        return 0;
    return 1;
}

enum { UNIT, SOLVE, REPLICA, PREPARATION, GUESS, CERTIFICATE, POLISH, NKERNELS };
/* the regions of the paths' solves follow the kernels' (region(NKERNELS + path, ...)) */
#define NREGIONS (NKERNELS + NPATHS)
static const char *NAMES[NKERNELS] = {
    "one degree-8 Horner evaluation (the unit)", "the whole solve (m2c_first_root_ex)",
    "the same steps, the replica's kernels called one after the other",
    "before the guess: validation, the preparation, the tests at 0 (a replica of solve's steps)",
    "the guess: Laguerre from 0 (speculate_first_root)",
    "its certificate: Bernstein test on (0, r (1 + 2^-20)] (bernstein_test)",
    "the polish: p', then compensated Newton (derivative, refine_root)"};

/* One region of the whole solves of the polynomials on one path, as region() below. */
static double path_region(int path, int total)
{
    double dep = 0, t0 = now_ns();
    for (int i = 0; i < total; i++) {
        const Input *in = &inputs[i];
        if (in->path != path)
            continue;
        double t = 0;
        int g = 0;
        m2c_first_root_ex(in->c, in->degree, in->tmax + 0x1p-1000 * dep, &t,
                          M2C_METHOD_INTERVAL, &g);
        dep = t;
    }
    double t1 = now_ns();
    sink = dep;
    return t1 - t0;
}

/* One region: every kept polynomial once through kernel `which`, each call's input made to
 * wait for the last call's result (adding 0x1p-1000 times it changes no input); from
 * NKERNELS on, the solves of one path (path_region). */
static double region(int which, int m, int total)
{
    static const double hc[9] = {1, -2, 3, -4, 5, -6, 7, -8, 1};
    if (which >= NKERNELS)
        return path_region(which - NKERNELS, total);
    double dep = 0, t0 = now_ns();
    for (int i = 0; i < m; i++) {
        Kept *k = &kept[i];
        double tiny = 0x1p-1000 * dep;
        switch (which) {
        case UNIT:
            dep = horner8(hc, 0.7 + tiny);
            break;
        case SOLVE: {
            double t = 0;
            int g = 0;
            m2c_first_root_ex(k->c, k->degree, k->tmax + tiny, &t, M2C_METHOD_INTERVAL, &g);
            dep = t;
            break;
        }
        case REPLICA: {
            double c[MAXN + 1], T = 0, r = 0, touch = 0, dip = 0, pT = 0, dp[MAXN], over = 0;
            Point a;
            int n = prepare_window(k->c, k->degree, k->tmax + tiny, c, &T, &a);
            int guess = speculate_first_root(c, n, T, &r, &touch, &dip, &over);
            double end = guess == OVERSHOT ? over : r, w = end + end * 0x1p-20;
            w = w < T ? w : T;
            if (bernstein_test(&a, n, w, &pT, NULL) == BERN_ONE) {
                derivative(c, n, dp);
                dep = refine_root(c, dp, n, 0, w, 1, guess == OVERSHOT ? 0 : PRECISE_NOW, r);
            }
            break;
        }
        case PREPARATION: {
            double c[MAXN + 1], T = 0;
            Point a;
            dep = prepare_window(k->c, k->degree, k->tmax + tiny, c, &T, &a) + c[0] + T;
            break;
        }
        case GUESS: {
            double r = 0, touch = 0, dip = 0, over = 0;
            dep = speculate_first_root(k->p, k->n, k->T + tiny, &r, &touch, &dip, &over) + r;
            break;
        }
        case CERTIFICATE: {
            double pT = 0;
            dep = bernstein_test(&k->a, k->n, k->w + tiny, &pT, NULL);
            break;
        }
        case POLISH: {
            double dp[MAXN];
            derivative(k->p, k->n, dp);
            dep = refine_root(k->p, dp, k->n, 0, k->w, 1, k->tol, k->r + tiny);
            break;
        }
        }
    }
    double t1 = now_ns();
    sink = dep;
    return t1 - t0;
}

int main(int argc, char **argv)
{
    int check = argc > 1 && strcmp(argv[1], "check") == 0;
    int regions = !check && argc > 1 ? atoi(argv[1]) : 201;
    if (regions < 1 || regions > 100001) {
        fprintf(stderr, "roots_kernels: regions must be 1..100001\n");
        return 2;
    }
    char line[16384];
    int total = 0, m = 0;
    while (fgets(line, sizeof line, stdin) && m < MAXPOLY) {
        Kept *k = &kept[m];
        char fam[32];
        int got = read_poly_line(line, fam, &k->tmax, &k->degree, k->c, MAXN);
        if (got < 0) {
            fprintf(stderr, "roots_kernels: bad line %d\n", total + 1);
            return 2;
        }
        if (got == 0)
            continue;
        Input *in = &inputs[total];
        in->tmax = k->tmax;
        in->degree = k->degree;
        memcpy(in->c, k->c, sizeof in->c);
        in->path = path_of(in);
        path_size[in->path]++;
        total++;
        m += prepare(k);
    }
    if (m == 0) {
        fprintf(stderr, "roots_kernels: no polynomial of %d is settled by the certified guess\n",
                total);
        return 2;
    }
    if (check) {
        /* the replica of solve()'s path gives the public answer, bit for bit */
        for (int i = 0; i < m; i++) {
            double t = refine_root(kept[i].p, kept[i].dp, kept[i].n, 0, kept[i].w, 1,
                                   PRECISE_NOW, kept[i].r);
            if (memcmp(&t, &kept[i].root, sizeof t) != 0) {
                printf("differ %d: %a against %a\n", i, t, kept[i].root);
                return 1;
            }
        }
        if (path_size[CERTIFIED] != m) {
            printf("paths: %d certified guesses, %d kept\n", path_size[CERTIFIED], m);
            return 1;
        }
        printf("ok %d of %d\n", m, total);
        return 0;
    }
    double empty = empty_region_ns();
    double *ns[NREGIONS];
    for (int j = 0; j < NREGIONS; j++) {
        ns[j] = malloc((size_t)regions * sizeof(double));
        if (ns[j] == NULL)
            return 2;
    }
    for (int rgn = 0; rgn < regions; rgn++)
        for (int j = 0; j < NREGIONS; j++) {
            int which = (j + rgn) % NREGIONS; /* the order rotates */
            int calls = which < NKERNELS ? m : path_size[which - NKERNELS];
            ns[which][rgn] = calls > 0 ? (region(which, m, total) - empty) / calls : 0;
        }
    double med[NREGIONS];
    for (int j = 0; j < NREGIONS; j++)
        med[j] = median(ns[j], regions);
    double unit = med[UNIT];
    printf("%d of %d polynomials settled by the certified guess; unit %.1f ns; %d regions.\n\n",
           m, total, unit, regions);
    printf("| kernel | ns per call | evaluations | share of the solve |\n|---|---:|---:|---:|\n");
    for (int j = 1; j < NKERNELS; j++)
        if (j != REPLICA)
        printf("| %s | %.0f | %.1f | %.0f %% |\n", NAMES[j], med[j], med[j] / unit,
               100 * med[j] / med[SOLVE]);
    printf("| (%s | %.0f | %.1f | %.0f %%) |\n", NAMES[REPLICA], med[REPLICA], med[REPLICA] / unit, 100 * med[REPLICA] / med[SOLVE]);
    double rest = med[SOLVE] - med[PREPARATION] - med[GUESS] - med[CERTIFICATE] - med[POLISH];
    printf("| the rest: calls, copies, and what the kernels cost more inside one solve than "
           "each on its own | %.0f | %.1f | %.0f %% |\n", rest, rest / unit, 100 * rest / med[SOLVE]);
    /* the paths: each one's solves in a region of their own, as the kernels' */
    double mean = 0;
    for (int j = 0; j < NPATHS; j++)
        mean += path_size[j] * med[NKERNELS + j] / unit / total;
    printf("\nEvery polynomial of the family by the path its solve takes (each path's solves "
           "timed in regions of their own, as the kernels above): %.1f evaluations a solve in "
           "the mean.\n\n", mean);
    printf("| path | polynomials | evaluations each | evaluations of the mean | share of the "
           "mean |\n|---|---:|---:|---:|---:|\n");
    for (int j = 0; j < NPATHS; j++) {
        double each = med[NKERNELS + j] / unit, part = path_size[j] * each / total;
        printf("| %s | %d | %.1f | %.1f | %.0f %% |\n", PATH_NAMES[j], path_size[j], each,
               part, mean > 0 ? 100 * part / mean : 0);
    }
    for (int j = 0; j < NREGIONS; j++)
        free(ns[j]);
    return 0;
}
