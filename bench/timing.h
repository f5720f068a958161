/* What the benchmark harnesses (roots_harness.c, roots_ab.c, roots_kernels.c, near_window.c,
 * horner_points.c) share: the clock, a median, the shuffle and its generator, and the unit of
 * cost.  Static, for one translation unit each (a harness that does not use a helper may warn
 * that it is unused). */
#ifndef BENCH_TIMING_H
#define BENCH_TIMING_H

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of v[0..n-1] (n >= 1); sorts v. */
static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* The cost of an empty timed region (median of 4001), subtracted from every timing. */
static double empty_region_ns(void)
{
    double empty[4001];
    for (int i = 0; i < 4001; i++) {
        double t0 = now_ns();
        double t1 = now_ns();
        empty[i] = t1 - t0;
    }
    return median(empty, 4001);
}

static unsigned long long rng_state = 88172645463325252ULL;
static unsigned long long xorshift(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return rng_state;
}

/* order[0 .. n-1] shuffled in place (Fisher-Yates): a new visiting order each sweep, so that a
 * solve never follows the same neighbours twice. */
static void shuffle(size_t order[], size_t n)
{
    for (size_t i = n; i > 1; i--) {
        size_t j = (size_t)(xorshift() % i);
        size_t tmp = order[i - 1];
        order[i - 1] = order[j];
        order[j] = tmp;
    }
}

/* Results go here, so that the compiler cannot drop the timed calls. */
static volatile double sink;

/* One line of roots_ab.c's and roots_kernels.c's input, FAMILY TMAX DEGREE C0 .. CN (hex
 * floats; family cut to 31 characters): 1 when read, 0 for a line without a word (skipped), -1
 * for a degree outside 0..maxn. */
static inline int read_poly_line(const char *line, char family[32], double *tmax, int *degree,
                                 double c[], int maxn)
{
    const char *s = line;
    char *e;
    int k = 0;
    if (sscanf(s, "%31s%n", family, &k) != 1)
        return 0;
    s += k;
    *tmax = strtod(s, &e);
    s = e;
    *degree = (int)strtol(s, &e, 10);
    if (e == s || *degree < 0 || *degree > maxn)
        return -1;
    s = e;
    for (int i = 0; i <= *degree; i++) {
        c[i] = strtod(s, &e);
        s = e;
    }
    return 1;
}

/* One degree-8 Horner evaluation: the unit of cost. */
__attribute__((noinline)) static double horner8(const double c[9], double x)
{
    double acc = c[8];
    for (int i = 7; i >= 0; i--)
        acc = acc * x + c[i];
    return acc;
}

/* Horner evaluations per timed region of the unit (one evaluation is about as long as reading
 * the clock: a batch keeps the clock's jitter from dominating). */
#define HORNER_BATCH 16

/* The unit as the harnesses that time solves one call at a time measure it: HORNER_BATCH
 * evaluations of polynomials i, i + 1, ... (mod n) of c8 at their points x8, each waiting for
 * the last (as the evaluations in a solve do); ns per evaluation, the empty region's cost
 * (overhead) subtracted. */
static double unit_region_ns(const double (*c8)[9], const double x8[], size_t n, size_t i,
                             double overhead)
{
    double v = 0;
    double t0 = now_ns();
    for (size_t h = 0; h < HORNER_BATCH; h++) {
        size_t j = (i + h) % n;
        v = horner8(c8[j], x8[j] + v * 0.0);
    }
    double t1 = now_ns();
    sink = v;
    return (t1 - t0 - overhead) / HORNER_BATCH;
}

#endif
