/* What the benchmark harnesses (roots_harness.c, roots_ab.c) share: the clock, a median, the
 * shuffle's generator and the unit of cost.  Static, for one translation unit each. */
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

#endif
