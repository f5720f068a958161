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
 * Output: a markdown table on stdout.  Argument 1: regions (default 201); argument "check":
 * prints "ok KEPT" or the first difference (tests/test_bench_kernels.py).
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
static const char *NAMES[NKERNELS] = {
    "one degree-8 Horner evaluation (the unit)", "the whole solve (m2c_first_root_ex)",
    "the same steps, the replica's kernels called one after the other",
    "before the guess: validation, the preparation, the tests at 0 (a replica of solve's steps)",
    "the guess: Laguerre from 0 (speculate_first_root)",
    "its certificate: Bernstein test on (0, r (1 + 2^-20)] (bernstein_test)",
    "the polish: p', then compensated Newton (derivative, refine_root)"};

/* One region: every kept polynomial once through kernel `which`, each call's input made to
 * wait for the last call's result (adding 0x1p-1000 times it changes no input). */
static double region(int which, int m)
{
    static const double hc[9] = {1, -2, 3, -4, 5, -6, 7, -8, 1};
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
        printf("ok %d of %d\n", m, total);
        return 0;
    }
    double empty = empty_region_ns();
    double *ns[NKERNELS];
    for (int j = 0; j < NKERNELS; j++) {
        ns[j] = malloc((size_t)regions * sizeof(double));
        if (ns[j] == NULL)
            return 2;
    }
    for (int rgn = 0; rgn < regions; rgn++)
        for (int j = 0; j < NKERNELS; j++) {
            int which = (j + rgn) % NKERNELS; /* the order rotates */
            ns[which][rgn] = (region(which, m) - empty) / m;
        }
    double med[NKERNELS];
    for (int j = 0; j < NKERNELS; j++)
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
    for (int j = 0; j < NKERNELS; j++)
        free(ns[j]);
    return 0;
}
