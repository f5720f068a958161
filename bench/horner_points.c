/*
 * horner_points.c -- what evaluating a polynomial at several points at once costs, in units of
 * one degree-8 Horner evaluation (bench/timing.h's unit), for issue 10's question whether
 * "Horner evaluated at several points at once" would make the solver cheaper.
 *
 * A solve's evaluations mostly wait for each other (Newton, Laguerre: the next point needs
 * this value), so one evaluation costs its chain of n dependent multiply-adds, and the
 * floating-point units idle most of that time.  Evaluations at k independent points run their
 * chains side by side; this measures, for k = 1, 2, 3, 4, 6, 8, the time of one call that
 * evaluates a degree-8 polynomial at k points, each call waiting for the last one's results
 * (as the unit does), and the same for the value with its first derivative (a Newton step's
 * evaluation) and with its first two (a Laguerre step's).
 *
 * The loops are unrolled completely (GCC unroll pragmas), so that the chains live in registers:
 * left to gcc -O2, the k = 3, 6 and 8 loops kept them in memory and cost twice as much, an
 * artefact of the loop, not of the evaluation (the runtime's own kernels are written out for
 * the same reason).
 *
 * Output: a markdown table on stdout.  Argument 1: timed regions per variant (default 2001);
 * argument "check": instead, compares every k-point function's values with k one-point
 * evaluations, bit for bit, and prints "ok" or the first difference (tests/test_bench_points.py).
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "timing.h"

#define NPOLY 1024
#define BATCH 16 /* calls per timed region, each waiting for the last */

/* p and its first D derivatives over k! (out[k K + j], k = 0..D) at K points: the K (D + 1)
 * Horner chains interleaved, step by step (D = 1: a Newton step's evaluation, D = 2: a
 * Laguerre step's) */
#define AT_POINTS(NAME, K, D)                                                                \
    __attribute__((noinline)) static void NAME(const double c[9], const double x[],         \
                                               double out[])                               \
    {                                                                                       \
        double t[D + 1][K];                                                                 \
        _Pragma("GCC unroll 8") for (int j = 0; j < K; j++) {                               \
            t[0][j] = c[8];                                                                 \
            _Pragma("GCC unroll 4") for (int k = 1; k <= D; k++) t[k][j] = 0;              \
        }                                                                                   \
        _Pragma("GCC unroll 8") for (int i = 7; i >= 0; i--)                                \
            _Pragma("GCC unroll 8") for (int j = 0; j < K; j++) {                           \
                _Pragma("GCC unroll 4") for (int k = D; k >= 1; k--)                        \
                    t[k][j] = t[k][j] * x[j] + t[k - 1][j];                                 \
                t[0][j] = t[0][j] * x[j] + c[i];                                            \
            }                                                                               \
        _Pragma("GCC unroll 8") for (int j = 0; j < K; j++)                                 \
            _Pragma("GCC unroll 4") for (int k = 0; k <= D; k++) out[k * K + j] = t[k][j];  \
    }
AT_POINTS(at1, 1, 0)
AT_POINTS(at2, 2, 0)
AT_POINTS(at3, 3, 0)
AT_POINTS(at4, 4, 0)
AT_POINTS(at6, 6, 0)
AT_POINTS(at8, 8, 0)
AT_POINTS(slope1, 1, 1)
AT_POINTS(slope4, 4, 1)
AT_POINTS(curve1, 1, 2)
AT_POINTS(curve4, 4, 2)

/* the unit itself (timing.h), in the kernels' form */
__attribute__((noinline)) static void unit(const double c[9], const double x[], double out[])
{
    out[0] = horner8(c, x[0]);
}

typedef void (*Kernel)(const double c[9], const double x[], double out[]);
typedef struct {
    const char *name;
    Kernel f;
    int points, outputs; /* outputs per point */
} Variant;

static const Variant VARIANTS[] = {
    {"p at 1 point (timing.h's horner8: the unit)", unit, 1, 1},
    {"p at 1 point", at1, 1, 1},          {"p at 2 points", at2, 2, 1},
    {"p at 3 points", at3, 3, 1},         {"p at 4 points", at4, 4, 1},
    {"p at 6 points", at6, 6, 1},         {"p at 8 points", at8, 8, 1},
    {"p, p' at 1 point", slope1, 1, 2},   {"p, p' at 4 points", slope4, 4, 2},
    {"p, p', p'' at 1 point", curve1, 1, 3}, {"p, p', p'' at 4 points", curve4, 4, 3},
};
#define NVARIANTS (int)(sizeof VARIANTS / sizeof VARIANTS[0])

static double coef[NPOLY][9], pts[NPOLY][8];

static void fill(void)
{
    for (int i = 0; i < NPOLY; i++) {
        for (int j = 0; j < 9; j++)
            coef[i][j] = (double)(xorshift() % 2000001) / 1000000.0 - 1.0;
        for (int j = 0; j < 8; j++)
            pts[i][j] = (double)(xorshift() % 1000001) / 1000000.0 + 0.25;
    }
}

/* Every k-point kernel against its one-point form, bit for bit. */
static int check(void)
{
    Kernel one[4] = {NULL, at1, slope1, curve1};
    for (int v = 0; v < NVARIANTS; v++) {
        const Variant *var = &VARIANTS[v];
        for (int i = 0; i < NPOLY; i++) {
            double out[24], single[3];
            var->f(coef[i], pts[i], out);
            for (int j = 0; j < var->points; j++) {
                one[var->outputs](coef[i], &pts[i][j], single);
                for (int o = 0; o < var->outputs; o++) {
                    double got = out[o * var->points + j];
                    if (memcmp(&got, &single[o], sizeof got) != 0) {
                        printf("%s: polynomial %d point %d output %d: %a, one at a time %a\n",
                               var->name, i, j, o, got, single[o]);
                        return 1;
                    }
                }
            }
        }
    }
    printf("ok\n");
    return 0;
}

int main(int argc, char **argv)
{
    fill();
    if (argc > 1 && strcmp(argv[1], "check") == 0)
        return check();
    int regions = argc > 1 ? atoi(argv[1]) : 2001;
    if (regions < 1)
        regions = 1;
    double overhead = empty_region_ns();
    double *t = malloc((size_t)regions * sizeof *t);
    double med[NVARIANTS], unit_check[NVARIANTS];
    /* variants interleaved region by region, so that the machine's drift hits all alike */
    double *all = malloc((size_t)regions * NVARIANTS * sizeof *all);
    for (int r = 0; r < regions; r++) {
        for (int v = 0; v < NVARIANTS; v++) {
            const Variant *var = &VARIANTS[v];
            double out[24] = {0}, x[8];
            double t0 = now_ns();
            for (int b = 0; b < BATCH; b++) {
                int i = (r * BATCH + b) % NPOLY;
                for (int j = 0; j < 8; j++) /* the next points wait for this call's values */
                    x[j] = pts[i][j] + out[j % var->points] * 0.0;
                var->f(coef[i], x, out);
            }
            double t1 = now_ns();
            sink = out[0];
            all[(size_t)r * NVARIANTS + (size_t)v] = (t1 - t0 - overhead) / BATCH;
        }
    }
    for (int v = 0; v < NVARIANTS; v++) {
        for (int r = 0; r < regions; r++)
            t[r] = all[(size_t)r * NVARIANTS + (size_t)v];
        med[v] = median(t, regions);
        unit_check[v] = med[v] / med[0];
    }
    printf("| evaluation | ns per call | degree-8 evaluations per call | per point |\n");
    printf("|---|---:|---:|---:|\n");
    for (int v = 0; v < NVARIANTS; v++)
        printf("| %s | %.1f | %.2f | %.2f |\n", VARIANTS[v].name, med[v], unit_check[v],
               unit_check[v] / VARIANTS[v].points);
    free(all);
    free(t);
    return 0;
}
