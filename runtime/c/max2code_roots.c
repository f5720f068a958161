/*
 * max2code_roots.c -- smallest root in (0, tmax] of a polynomial of degree <= 8.
 * See max2code_roots.h for the contract and the methods.  This file holds
 * what every part shares and the entry points; the algorithm is in the
 * parts it includes from roots/ (listed below), one translation unit.
 */
#include "max2code_roots.h"

#include <complex.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#ifndef M2C_NO_GSL
#include <gsl/gsl_errno.h>
#include <gsl/gsl_poly.h>
#endif

#define MAXN M2C_MAX_DEGREE

/* Every a * x + b stays a multiply, then an add, wherever the compiler
 * could fuse it (the fma-instruction copies below included): the answers
 * are the same bits as the other runtimes', with no flag of the user's.
 * Clang fuses within an expression by default and honours the standard
 * pragma.  GCC ignores that one; in its GNU modes (the default) it fuses
 * wherever the target has the instruction -- in the fma copies even
 * without -mfma: a plain gcc -O2 build differed in 36 of the 11,360
 * answers of tests/runtime/test_build_variants.py -- and its own pragma
 * turns that off for this file (GCC 12, -O2 and above: the same code as
 * -ffp-contract=off, compared instruction for instruction; in C11 mode,
 * the same as before; at -O1 it changes an inlining decision, not an
 * answer).  The manual calls the optimize pragma unfit for production in
 * general; this one sets the single option that keeps the answers the
 * other runtimes'.  Both end with the file (pushed, popped below).  A
 * user's -ffp-contract=fast still overrides Clang's pragma. */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#endif

/* x + i y with no arithmetic on the parts (x + I y would turn an infinite
 * y into a NaN real part).  C11's CMPLX, which glibc's <complex.h> leaves
 * undefined for Clang (it asks for GCC 4.7): there, the parts are copied
 * into place (C11 6.2.5: a complex has the representation of an array of
 * its two parts). */
#ifdef CMPLX
#define COMPLEX_OF(x, y) CMPLX(x, y)
#else
static double complex complex_of(double x, double y)
{
    double parts[2] = {x, y};
    double complex z;
    memcpy(&z, parts, sizeof z);
    return z;
}
#define COMPLEX_OF(x, y) complex_of(x, y)
#endif

/* Is n a constant of at most k where this code is compiled?  In GCC's
 * degree-specialised copies (DEGREE_CLONES, below) every call is inlined
 * with n a constant, and a written-out form for low degrees pays there;
 * elsewhere it is mostly 0 at compile time, and the general code keeps its
 * loops (the same forms chosen by a test on n at run time cost degrees 12
 * and 16 8 % of their time, by where they moved its code).  Each use is
 * decided on its own: Clang's flatten inlines only a copy's direct
 * callees, so n is a constant in taylor_table there but not in point_at or
 * binomial_sums (whose form for degree 4 runs under GCC only), and GCC may
 * fold it to 1 outside the copies too.  So a use only chooses between forms
 * that are right for any n, and no use counts on another's answer:
 * taylor_table hands its choice to point_at in the table. */
#if defined(__GNUC__)
#define CONSTANT_AT_MOST(n, k) (__builtin_constant_p(n) && (n) <= (k))
#else
#define CONSTANT_AT_MOST(n, k) 0
#endif

/* Rare paths kept out of the hot function's frame and registers. */
#if defined(__GNUC__)
#define NOINLINE __attribute__((noinline))
#else
#define NOINLINE
#endif

/* Cost accounting for the benchmark (bench/roots.py --counts), compiled in only with
 * -DM2C_COUNT: multiply-adds by phase (0 preparation, 1 Budan-Fourier counts and exclusion
 * tests, 2 Newton polishing of an isolated root, 3 the derivative method), Newton steps
 * plain/compensated, Taylor points, derivative-method calls.  Not thread-safe; never in a
 * normal build. */
#ifdef M2C_COUNT
double m2c_count[10];
static int count_phase;
#define COUNT_MADDS(k) (m2c_count[count_phase] += (k))
#define COUNT(i) (m2c_count[i] += 1)
#define PHASE(p) (count_phase = (p))
#else
#define COUNT_MADDS(k) ((void)0)
#define COUNT(i) ((void)0)
#define PHASE(p) ((void)0)
#endif
#define UNIT_ROUNDOFF (DBL_EPSILON / 2)
#define PI_D 3.14159265358979323846

/* |x| up to 2^120 for a polynomial of degree m <= 8, 2^60 above: with
 * |c_i| < 1 (normalised) and derivative coefficients at most 16!/m! (< 2^45),
 * Horner cannot overflow (2^29 * 2^960 * 9 and 2^45 * 2^960 * 17 < DBL_MAX).
 * Beyond it the evaluation is scaled by powers of two. */
#define SAFE_LOW 0x1p120
#define SAFE_HIGH 0x1p60

/* Newton/bisection iteration cap: geometric bisection needs ~11 steps to
 * reach a factor-2 bracket from the whole double range, then <= 53 more. */
#define MAX_ITER 200

/* A complex root counts as real (double, grazing) for the GSL and closed
 * methods when |imag| <= REAL_TOL |z|: a double root perturbed by rounding
 * splits by about sqrt(eps). */
#define REAL_TOL 1.4901161193847656e-08 /* sqrt(DBL_EPSILON) */

/* The parts (runtime/c/roots/), in dependency order: each uses the ones
 * before it, and the functions declared ahead where they are.  Included,
 * not compiled apart: every build compiles this one file, as before, and
 * the compiler sees and inlines the static helpers across the parts as in
 * one file (the same object code).  Named .inc, not .c, so that no build
 * and no glob over *.c compiles a part alone. */
#include "roots/prepare.inc"
#include "roots/evaluate.inc"
#include "roots/quadratic.inc"
#include "roots/newton.inc"
#include "roots/bernstein.inc"
#include "roots/isolate.inc"
#include "roots/derivative.inc"
#include "roots/interval.inc"
#include "roots/spread.inc"
#include "roots/gsl.inc"
#include "roots/quartic.inc"
#include "roots/early.inc"
#include "roots/never_late.inc"

/* ------------------------------------------------------------------ */
/* Entry points                                                         */
/* ------------------------------------------------------------------ */

/* The leading terms reduce dropped from c_in (of the given degree; n kept
 * after the factors of t it divided out): *m of them from the returned
 * pointer on, the last nonzero.  *m = 0 where it dropped none. */
static const double *dropped_terms(const double c_in[], int degree, int n, int *m)
{
    int low = 0, top = degree;
    while (c_in[low] == 0)
        low++;
    while (top > low + n && c_in[top] == 0)
        top--;
    *m = top - (low + n);
    return c_in + low + n + 1;
}

/* solve() once the coefficients span at most 2^MAX_SPREAD (always, but for
 * extremes): scaled exactly, then by degree and method. */
static int solve_normalised(double c[], const int e[], const int nz[], int n,
                            int emax, double tu, int method, double eps,
                            double failed_w, double bound, const double dropped[], int m,
                            double *root, int *g)
{
    int closed = method == M2C_METHOD_CLOSED && n <= 4;
    int interval = n > 2 && method != M2C_METHOD_GSL && !closed;
    /* the interval method wants p(0) > 0: p = -c has the same roots (the
     * sign goes into the exact scaling: no pass of its own) */
    double sign = interval && c[0] < 0 ? -1 : 1;
    int E = normalise(c, n, emax, sign);
    /* skin < 0: no graze check; else the skin in the normalised units */
    double skin = method == M2C_METHOD_INTERVAL_NOGRAZE ? -1
                  : eps == 0                           ? 0
                                                       : ldexp(eps, -E);
    if (n <= 2) {
        int found;
        if (n == 1) {
            *root = -c[0] / c[1];
            found = *root > 0 && *root <= tu;
        } else {
            found = first_root_quadratic(c, 0, tu, skin, root, g);
        }
        if (found && skin >= 0 && m > 0)
            late_low_degree(c, n, dropped, m, E, root, g);
        return found;
    }
    if (method == M2C_METHOD_GSL)
        return first_root_gsl(c, n, tu, root, g);
    if (closed)
        return first_root_closed(c, n, tu, root, g);
    /* every positive root lies below the bound: a smaller window, fewer
     * steps (with a skin, Fujiwara's on every root, as the skin's contact
     * need not be near a positive root) */
    /* (the exponents before scaling: the same; reduce's where it has it) */
    double B = bound >= 0 ? bound : root_bound(e, nz, skin > 0 ? NULL : c, n);
    double T = tu < B ? tu : B;      /* (fmin is a library call) */
    int found = T > 0 ? first_root_interval_fixed(c, n, T, skin, failed_w, root, g) : 0;
    if (!found)
        return 0;
    /* (with a contact skin too: a touch within it stands where p is not
     * certainly negative, as any touch) */
    if (skin >= 0 && m == 0 && found != SCANNED)
        never_late(c, n, NULL, 0, root, g);
    else if (skin >= 0 && m == 0)
        late_scanned(c, n, root, g);
    else if (skin >= 0)
        late_with_tail(c, n, dropped, m, sign, E, root, g);
    return 1;
}

/* The common path of every entry point: eps is the contact skin (>= 0, in
 * the units of c_in), ignored without the graze check. */
static ALWAYS_INLINE int solve_core(const double c_in[], int degree, double tmax,
                                    int method, double eps, double *t, int *graze)
{
    if (!input_is_valid(c_in, degree, tmax, t))
        return -1;
    if (method < 0 || method >= M2C_METHOD_COUNT)
        return -1;
#ifdef M2C_NO_GSL
    if (method == M2C_METHOD_GSL)
        return -1; /* not built in */
#endif
    if (!(eps >= 0 && eps < INFINITY))
        return -1;
    double c[MAXN + 1];
    int e[MAXN + 1], nz[MAXN + 1], emax, g = 0, found;
    Scan sc = load_coefficients(c_in, degree, c, e, nz);
    if (!sc.finite)
        return -1; /* a NaN or an infinity */
    PHASE(0);
    COUNT(8);
    /* Where the early exits below apply: the interval methods, no skin,
     * c_0 != 0 */
    int early = c[0] != 0 && eps == 0 &&
                (method == M2C_METHOD_INTERVAL || method == M2C_METHOD_INTERVAL_NOGRAZE);
    /* Descartes on the input: no sign change, c_0 != 0, no root in (0, inf)
     * (and none of p = +-c's envelope q either, whose coefficients have
     * p's signs): the interval methods would clear it, after the
     * preparation that would be most of such a solve's cost */
    if (early && sc.changes == 0)
        return 0;
    /* Step 0a': AM-GM, with tmax = inf (outweighed) */
    if (early && degree >= 3 && tmax == INFINITY && outweighed(c, degree))
        return 0;
    /* Step 0b: the window's first test, before the preparation; where it
     * fails, the window [0, tmax] it failed on (0: not tried), which the
     * default method then does not test again */
    double failed_w = 0;
    int cleared = -1;
    if (early && degree >= 3 && tmax < INFINITY) {
        cleared = cleared_at_once(c, e, nz, degree, tmax, sc);
        if (cleared > 0)
            return 0;
        failed_w = cleared == 0 && method == M2C_METHOD_INTERVAL ? tmax : 0;
    }
    /* (a test step 0b ran -- only where c_n, c_0 != 0 and leading_far shows
     * the leading term far from negligible over [0, tmax] -- means reduce
     * would drop nothing: the same checks, not repeated) */
    /* (every_root as solve_normalised's window: a skin, and a graze check to use it) */
    double bound = -1;
    int n = cleared == 0 ? degree
                         : reduce(c, e, nz, degree, &tmax,
                                  eps > 0 && method != M2C_METHOD_INTERVAL_NOGRAZE, sc.emax,
                                  &bound);
    if (n <= 0)
        return 0;
    double root = 0;
    emax = sc.emax;
    int sp = n == degree ? sc.emax - sc.emin /* reduce dropped nothing */
                         : spread(e, nz, n, &emax);
    int m = 0;
    const double *dropped = n == degree ? c_in : dropped_terms(c_in, degree, n, &m);
    if (sp > MAX_SPREAD)
        found = first_root_sliced(c, n, tmax, eps, method == M2C_METHOD_INTERVAL_NOGRAZE,
                                  dropped, m, &root, &g);
    else
        found = solve_normalised(c, e, nz, n, emax, tmax, method, eps, failed_w, bound,
                                 dropped, m, &root, &g);
    if (!found)
        return 0;
    /* a root that underflows to 0 or overflows is not representable: none */
    if (!(root > 0 && root <= tmax && root < INFINITY))
        return 0;
    *t = root;
    if (graze != NULL)
        *graze = g;
    return 1;
}

/* solve_core, by its copy for the degree where there is one (see
 * first_root_interval_fixed; measured with it). */
#if DEGREE_CLONES
#define SOLVE_CLONE(N)                                                               \
    NOINLINE __attribute__((flatten)) static int solve_##N(                         \
        const double c_in[], double tmax, int method, double eps, double *t,         \
        int *graze)                                                                  \
    {                                                                                \
        return solve_core(c_in, N, tmax, method, eps, t, graze);                     \
    }
SOLVE_CLONE(2)
SOLVE_CLONE(4)
SOLVE_CLONE(8)
#undef SOLVE_CLONE
#endif

static int solve(const double c_in[], int degree, double tmax, int method,
                 double eps, double *t, int *graze)
{
#if DEGREE_CLONES
    if (degree == 8)
        return solve_8(c_in, tmax, method, eps, t, graze);
    if (degree == 4)
        return solve_4(c_in, tmax, method, eps, t, graze);
    if (degree == 2)
        return solve_2(c_in, tmax, method, eps, t, graze);
#endif
    return solve_core(c_in, degree, tmax, method, eps, t, graze);
}

int m2c_first_root_ex(const double c[], int degree, double tmax, double *t,
                      int method, int *graze)
{
    return solve(c, degree, tmax, method, 0, t, graze);
}

int m2c_first_root_skin(const double c[], int degree, double tmax, double eps,
                        double *t, int *graze)
{
    return solve(c, degree, tmax, M2C_METHOD_INTERVAL, eps, t, graze);
}

int m2c_first_root_method(const double c[], int degree, double tmax, double *t,
                          int method)
{
    return solve(c, degree, tmax, method, 0, t, NULL);
}

int m2c_first_root(const double c[], int degree, double tmax, double *t)
{
    return solve(c, degree, tmax, M2C_METHOD_INTERVAL, 0, t, NULL);
}

int m2c_first_roots(const double c[], int m, int degree, double tmax,
                    double eps, double t[], int status[])
{
    if (c == NULL || t == NULL || m < 0 || degree < 0 || degree > MAXN)
        return -1;
    int found = 0;
    size_t stride = (size_t)degree + 1;
    for (int i = 0; i < m; i++) {
        double r = NAN;
        int st = solve(c + (size_t)i * stride, degree, tmax, M2C_METHOD_INTERVAL,
                       eps, &r, NULL);
        t[i] = st == 1 ? r : NAN;
        if (status != NULL)
            status[i] = st;
        found += st == 1;
    }
    return found;
}

/* (the contraction setting above ends with this file) */
#if defined(__clang__)
#pragma STDC FP_CONTRACT DEFAULT
#elif defined(__GNUC__)
#pragma GCC pop_options
#endif
