/*
 * roots_harness.c -- timing and answers of the C runtime's root methods, for
 * bench/roots.py (which writes the input, builds this file with -O2 against
 * runtime/c/max2code_roots.c and reads the output).
 *
 * Input (stdin), one polynomial a line:   TMAX DEGREE C0 .. CDEGREE   (hex floats)
 * Argument 1: number of sweeps (default 7).  Argument 2: the methods to run, as
 * a count from 0 (default 4: all; 1: only INTERVAL, for the runtime comparison).
 *
 * The unit of cost: each sweep also times, the same way, evaluations of a
 * degree-8 polynomial by Horner's rule (a separate, not inlined function, on
 * the polynomials' coefficients padded to degree 8, at a point of their
 * window), HORNER_BATCH different ones per timed region, each waiting for
 * the last (as the evaluations in a solve do), so that the clock's own
 * jitter (one evaluation is about as long as reading the clock) does not
 * dominate; the median per evaluation is printed as
 * "# horner8_ns", so that solve times can be expressed in evaluations
 * measured in the same run.
 *
 * Built with -DM2C_COUNT (against the runtime built so too) and run with the
 * argument "count", it solves each polynomial once by INTERVAL and prints the
 * runtime's cost accounting instead: "INDEX" then the ten counters of
 * m2c_count (multiply-adds by phase, Newton steps, Taylor points, ...).
 *
 * Each sweep visits every polynomial once, in an order shuffled anew per
 * sweep, and for each calls every method once, in a rotating order; every call
 * is timed on its own with clock_gettime(CLOCK_MONOTONIC) (TSC clock source
 * here).  So a solve never follows a solve of the same polynomial by the same
 * method: branch predictors and caches see what an engine would, a stream of
 * different polynomials.  The cost of an empty timed region (measured here,
 * median of many) is subtracted.
 *
 * Output, one line per polynomial and method:
 *   INDEX METHOD STATUS T GRAZE NS_MEDIAN
 * with T as %a (hex, exact) and NS_MEDIAN the median over the sweeps.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "max2code_roots.h"
#include "timing.h"

#define NMETHODS 4
#define MAXSWEEPS 31

typedef struct {
    double tmax;
    int degree;
    double c[M2C_MAX_DEGREE + 1];
} Poly;

#ifdef M2C_COUNT
extern double m2c_count[10];
#endif

int main(int argc, char **argv)
{
    int counting = argc > 1 && strcmp(argv[1], "count") == 0;
    int sweeps = argc > 1 && !counting ? atoi(argv[1]) : 7;
    if (sweeps < 1) sweeps = 1;
    if (sweeps > MAXSWEEPS) sweeps = MAXSWEEPS;
    int nmethods = argc > 2 ? atoi(argv[2]) : NMETHODS;
    if (nmethods < 1 || nmethods > NMETHODS) nmethods = NMETHODS;

    size_t cap = 1024, n = 0;
    Poly *ps = malloc(cap * sizeof *ps);
    char line[8192];
    while (fgets(line, sizeof line, stdin) != NULL) {
        char *p = line, *end;
        Poly q;
        q.tmax = strtod(p, &end);
        if (end == p) continue;
        p = end;
        q.degree = (int)strtol(p, &end, 10);
        p = end;
        for (int i = 0; i <= q.degree && i <= M2C_MAX_DEGREE; i++) {
            q.c[i] = strtod(p, &end);
            p = end;
        }
        if (n == cap) {
            cap *= 2;
            ps = realloc(ps, cap * sizeof *ps);
        }
        ps[n++] = q;
    }

#ifdef M2C_COUNT
    if (counting) {
        for (size_t i = 0; i < n; i++) {
            double t;
            memset(m2c_count, 0, sizeof m2c_count);
            m2c_first_root_ex(ps[i].c, ps[i].degree, ps[i].tmax, &t, 0, NULL);
            printf("%zu", i);
            for (int k = 0; k < 10; k++)
                printf(" %.0f", m2c_count[k]);
            printf("\n");
        }
        free(ps);
        return 0;
    }
#else
    (void)counting;
#endif
    double overhead = empty_region_ns();

    double *ns = malloc(n * NMETHODS * (size_t)sweeps * sizeof *ns);
    int *status = malloc(n * NMETHODS * sizeof *status);
    int *graze = malloc(n * NMETHODS * sizeof *graze);
    double *root = malloc(n * NMETHODS * sizeof *root);
    size_t *order = malloc(n * sizeof *order);
    for (size_t i = 0; i < n; i++) order[i] = i;
    double *hns = malloc(n * (size_t)sweeps * sizeof *hns);
    double (*c8)[9] = calloc(n, sizeof *c8);
    double *x8 = malloc(n * sizeof *x8);
    for (size_t i = 0; i < n; i++) {
        for (int j = 0; j <= ps[i].degree && j <= 8; j++)
            c8[i][j] = ps[i].c[j];
        x8[i] = isfinite(ps[i].tmax) ? 0.5 * ps[i].tmax : 1.0;
    }
    size_t nh = 0;

    for (int s = 0; s < sweeps; s++) {
        shuffle(order, n);
        for (size_t k = 0; k < n; k++) {
            size_t i = order[k];
            const Poly *q = &ps[i];
            hns[nh++] = unit_region_ns((const double (*)[9])c8, x8, n, i, overhead);
            for (int mm = 0; mm < nmethods; mm++) {
                int m = (mm + (int)k) % nmethods;
                double t = NAN;
                int g = 0;
                double t0 = now_ns();
                int st = m2c_first_root_ex(q->c, q->degree, q->tmax, &t, m, &g);
                double t1 = now_ns();
                sink = t;
                ns[(i * NMETHODS + (size_t)m) * (size_t)sweeps + (size_t)s] = t1 - t0 - overhead;
                status[i * NMETHODS + (size_t)m] = st;
                root[i * NMETHODS + (size_t)m] = st == 1 ? t : NAN;
                graze[i * NMETHODS + (size_t)m] = st == 1 ? g : 0;
            }
        }
    }
    printf("# overhead_ns %.2f sweeps %d\n", overhead, sweeps);
    printf("# horner8_ns %.2f\n", median(hns, (int)nh));
    for (size_t i = 0; i < n; i++)
        for (int m = 0; m < nmethods; m++) {
            size_t k = i * NMETHODS + (size_t)m;
            double med = median(&ns[k * (size_t)sweeps], sweeps);
            printf("%zu %d %d %a %d %.2f\n", i, m, status[k], root[k], graze[k], med);
        }
    free(ns);
    free(status);
    free(graze);
    free(root);
    free(order);
    free(hns);
    free(c8);
    free(x8);
    free(ps);
    return 0;
}
