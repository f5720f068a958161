/*
 * max2code_roots.c -- smallest root in (0, tmax] of a polynomial of degree <= 8.
 * See max2code_roots.h for the contract and the methods.
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

/* ------------------------------------------------------------------ */
/* Validation and preparation                                           */
/* ------------------------------------------------------------------ */

static int input_is_valid(const double c[], int degree, double tmax,
                          const double *t)
{
    if (c == NULL || t == NULL || degree < 0 || degree > MAXN)
        return 0;
    return !isnan(tmax) && tmax > 0; /* the coefficients: load_coefficients */
}

/* ilogb(x) for finite nonzero x, read from the bits: it runs for every
 * coefficient of every solve, and ilogb is a library call. */
static int exponent_of(double x)
{
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    int e = (int)((b >> 52) & 0x7ff);
    return e != 0 ? e - 1023 : ilogb(x); /* subnormal: rare */
}

/* 2^e, exact, for DBL_MIN_EXP - 1 <= e <= DBL_MAX_EXP - 1 (normal range). */
static double pow2(int e)
{
    uint64_t b = (uint64_t)(e + 1023) << 52;
    double x;
    memcpy(&x, &b, sizeof x);
    return x;
}

/* ceil(num / den) for 0 < den <= MAXN and |num| < 2^12, without a division:
 * this runs n times per solve (twice with tmax = inf), and an integer
 * division is slow.  num + 2^12 den + den - 1 = x is positive and below
 * 2^17, and for such x, floor(x / den) = floor(x ceil(2^32 / den) / 2^32)
 * (the excess of den ceil(2^32 / den) over 2^32 is below den, and x den <
 * 2^32).  Checked for every num and den by tests/runtime/test_c_kernels.py. */
static int ceil_div(int num, int den)
{
#define M(d) ((0x100000000ULL + (d) - 1) / (d))
    static const uint64_t MAGIC[MAXN + 1] = {
        0,     M(1),  M(2),  M(3),  M(4),  M(5),  M(6),  M(7),  M(8),
        M(9),  M(10), M(11), M(12), M(13), M(14), M(15), M(16)};
#undef M
    uint64_t x = (uint64_t)(num + 4096 * den + den - 1);
    return (int)((x * MAGIC[den]) >> 32) - 4096;
}

/* What load_coefficients reads off the bits besides the exponents, in the
 * same pass: the largest and smallest exponent of the nonzero coefficients
 * (the spread, unless reduce drops terms) and the number of sign changes
 * (zeros skipped: Descartes' bound on the positive roots, which clears a
 * solve with no sign change before any preparation). */
typedef struct {
    int finite;  /* no NaN, no infinity */
    int emax;    /* INT_MIN when every coefficient is 0 */
    int emin;
    int changes;
} Scan;

/* load_coefficients for any coefficients: zeros skipped in the sign
 * changes, subnormals' exponents by ilogb, infinities and NaN flagged. */
NOINLINE static Scan load_any(const double src[], int n, double c[], int e[],
                              int nz[])
{
    int bad = 0, hi = INT_MIN, lo = INT_MAX, changes = 0;
    uint64_t last = 0; /* the sign bit of the last nonzero, + 1; 0: none yet */
    for (int i = 0; i <= n; i++) {
        double x = src[i];
        uint64_t b;
        memcpy(&b, &x, sizeof b);
        c[i] = x;
        int be = (int)((b >> 52) & 0x7ff);
        bad |= be == 0x7ff;
        int z = (b << 1) != 0;
        nz[i] = z;
        int ei = be != 0 ? be - 1023 : z ? ilogb(x) : 0; /* subnormal: rare */
        e[i] = ei;
        int h = z ? ei : INT_MIN, l = z ? ei : INT_MAX;
        hi = h > hi ? h : hi;
        lo = l < lo ? l : lo;
        uint64_t sg = (b >> 63) + 1;
        changes += z & (last != 0) & (last != sg);
        last = z ? sg : last;
    }
    return (Scan){!bad, hi, lo, changes};
}

/* Copies src[0..n] to c (which may be src) and reads the exponents from the
 * bits in the same pass: e[i] = ilogb(c[i]) and nz[i] = (c[i] != 0), e[i] = 0
 * for zeros; .finite is 0 when a coefficient is not (invalid input).
 * The preparation below works on these integers: a solve that is cleared at
 * once is mostly preparation, and the floating-point forms of these tests
 * cost a dozen Horner evaluations.  (A plain copy loop became `rep movsq`,
 * a sixth of such a solve.) */
static Scan load_coefficients(const double src[], int n, double c[], int e[],
                              int nz[])
{
    /* The common case first: every coefficient a normal number, so no
     * zeros to skip and no subnormal's ilogb (measured: bench/roots_ab.py
     * --instructions, 187 fewer a solve, 0.91 of a solve the early bound
     * settles, 0.97 of a generic octic's); anything else --
     * a zero, a subnormal, an infinity or a NaN -- has them read again by
     * load_any (out of line, so that its registers do not weigh on this
     * loop), with the same results where both apply. */
    {
        int hi = INT_MIN, lo = INT_MAX, changes = 0;
        uint64_t prev;
        memcpy(&prev, &src[0], sizeof prev);
        for (int i = 0; i <= n; i++) {
            double x = src[i];
            uint64_t b;
            memcpy(&b, &x, sizeof b);
            c[i] = x;
            int ei = (int)((b >> 52) & 0x7ff) - 1023;
            e[i] = ei;
            nz[i] = 1;
            hi = ei > hi ? ei : hi;
            lo = ei < lo ? ei : lo;
            changes += (int)((b ^ prev) >> 63);
            prev = b;
        }
        /* (biased exponent 0 -- a zero or a subnormal -- reads as -1023,
         * 0x7ff -- an infinity or a NaN -- as 1024) */
        if (lo > -1023 && hi < 1024)
            return (Scan){1, hi, lo, changes};
    }
    return load_any(src, n, c, e, nz);
}

/* Fujiwara bound 2 max |c_i/c_n|^(1/(n-i)), each ratio rounded up to a power
 * of two using exponents only (no overflow, no logs): every root z has
 * |z| < 2^(the result).  e, nz: the exponents of c[0..n] (load_coefficients;
 * only their differences matter, so any common power-of-two scaling of c
 * gives the same bound); nz[n].  INT_MIN when all c_i (i < n) are 0.
 * With the coefficients c (else NULL), the maximum runs over the c_i of
 * the sign opposite to c_n only: Kioustelidis' bound, which bounds the
 * positive roots alone (all the solvers look for) and ignores the terms
 * that only push complex and negative roots out -- INT_MIN, as it should,
 * where no sign differs from c_n's (no sign change: no positive root).
 * Measured as the window's end with tmax = inf (bench/roots_ab.py
 * --instructions against Fujiwara's): no root with tmax = inf 0.80, no
 * root in the window 0.92, the other families within 1 %; the same
 * answers, bit for bit.  (Branch-free: which term gives the maximum, and
 * the signs, are data.) */
static inline int bound_exponent(const int e[], const int nz[], const double c[],
                                 int n, const int only)
{
    int en = e[n];
    uint64_t sn = 0; /* c_n's bits (with only) */
    if (only)
        memcpy(&sn, &c[n], sizeof sn);
    int best = INT_MIN;
    for (int i = 0; i < n; i++) {
        /* |c_i / c_n| < 2^(e_i + 1 - e_n) */
        int q = ceil_div(e[i] + 1 - en, n - i);
        /* c_i's bits; without only, a sign opposite to sn's: every c_i counts */
        uint64_t si = sn ^ 0x8000000000000000ULL;
        if (only)
            memcpy(&si, &c[i], sizeof si);
        int use = -(nz[i] & (int)((si ^ sn) >> 63)); /* 0 or -1 */
        q = (q & use) | (INT_MIN & ~use); /* (a mask: gcc made a branch of ?:) */
        best = q > best ? q : best;
    }
    return best == INT_MIN ? INT_MIN : best + 1;
}

static int root_bound_exponent(const int e[], const int nz[], const double c[],
                               int n)
{
    return c != NULL ? bound_exponent(e, nz, c, n, 1) : bound_exponent(e, nz, NULL, n, 0);
}

/* The bound as a double (DBL_MAX beyond it); 0 when no c_i (i < n) counts
 * (root_bound_exponent: c NULL or not). */
static double root_bound(const int e[], const int nz[], const double c[], int n)
{
    int b = root_bound_exponent(e, nz, c, n);
    if (b == INT_MIN)
        return 0;
    if (b >= DBL_MAX_EXP)
        return DBL_MAX;
    return b >= DBL_MIN_EXP - 1 ? pow2(b) : ldexp(1.0, b);
}

/* |a| T^j <= k |b| (a, b, k nonzero, T > 0 finite), without leaving the
 * double range: mantissas in [1, 2), exponents apart.  (Rare: only where
 * the plain products leave the normal range.) */
static int scaled_le(double a, double T, int j, double k, double b)
{
    int et = exponent_of(T);
    double mt = ldexp(T, -et);
    int ea = exponent_of(a), eb = exponent_of(b), ek = exponent_of(k);
    double ma = ldexp(fabs(a), -ea);
    double mb = ldexp(fabs(b), -eb) * ldexp(k, -ek);
    for (int s = 0; s < j; s++) {
        ma *= mt;
        int e = ma >= 2;
        ma = e ? 0.5 * ma : ma;
        ea += et + e;
    }
    int e = mb >= 2;
    mb = e ? 0.5 * mb : mb;
    eb += ek + e;
    return ea < eb || (ea == eb && ma <= mb);
}

/* Does the exponents alone show the leading term far from negligible over
 * [0, T] (T finite): |c_n| T^(n-i) above 4 n eps |c_i| by a factor 8 for
 * every i, beyond all the roundings of the comparison?  Almost always, and
 * then leading_negligible needs no floating-point loop.  emax: a bound on
 * every e_i of a nonzero c_i (load_coefficients' largest; INT_MIN, every
 * c_i 0, leaves it to the loop): the least of the left sides against it
 * settles every term at once, as it
 * almost always does (measured: bench/roots_ab.py --instructions, about 100
 * fewer a solve on every family that reaches step 0b or, with tmax = inf,
 * reduce). */
static int leading_far(const int e[], const int nz[], int n, double T, int emax)
{
    if (!(T >= DBL_MIN && T <= DBL_MAX))
        return 0;
    /* T >= 2^eT, k < 2^(ek + 1), |c| in [2^e, 2^(e + 1)) */
    int eT = exponent_of(T), ek = exponent_of(4.0 * n * DBL_EPSILON), far = 1;
    if (emax > INT_MIN && e[n] + (eT >= 0 ? eT : n * eT) >= emax + ek + 5)
        return 1;
    int lhs = e[n] + eT; /* a lower bound on log2 |c_n| T^(n-i) */
    for (int i = n - 1; i >= 0; i--, lhs += eT)
        far &= !nz[i] | (lhs >= e[i] + ek + 5); /* (no branches) */
    return far;
}

/* Is the leading term negligible over [0, T] (see header)?  Compared term by
 * term as |c_n| T^(n-i) <= k |c_i|; where a side leaves the normal range
 * (T^2 underflowed to 0 for T = 2^-1020, and every leading term looked
 * negligible), in exponents (scaled_le).  Almost always no term comes
 * near: when the exponents alone show |c_n| T^(n-i) above k |c_i| by a
 * factor 8 for every i (beyond all the roundings of the comparison), the
 * answer is no without the loop.  T = inf: no (reduce gives a finite T). */
static int leading_negligible(const double c[], const int e[], const int nz[],
                              int n, double tmax, int emax)
{
    double T = tmax;
    if (isinf(T))
        return 0;
    double k = 4.0 * n * DBL_EPSILON;
    if (leading_far(e, nz, n, T, emax))
        return 0;
    double Tp = 1.0;
    for (int i = n - 1; i >= 0; i--) {
        Tp *= T; /* T^(n-i) */
        if (c[i] == 0)
            continue;
        double lhs = fabs(c[n]) * Tp, rhs = k * fabs(c[i]);
        if (Tp >= DBL_MIN && Tp <= DBL_MAX && lhs >= DBL_MIN && lhs <= DBL_MAX &&
                    rhs >= DBL_MIN
                ? lhs <= rhs
                : scaled_le(c[n], T, n - i, k, c[i]))
            return 1;
    }
    return 0;
}

/* Drop zero/negligible leading terms and factors of t; returns the degree
 * left, or -1 for the zero polynomial.  c and its exponents (e, nz) are
 * modified in place.  emax: load_coefficients' largest exponent, which
 * stays a bound on every e_i left (leading_far).
 * *tmax = inf: the window the leading term is weighed over is (0, K], K the
 * bound on the positive roots of the polynomial as it stands (Kioustelidis';
 * with a contact skin and a graze check, every_root: Fujiwara's on every
 * root), which holds
 * every root there is to find.  Where the term is negligible over it, it is
 * dropped and *tmax becomes K: the rest may have roots beyond K that the
 * whole polynomial has not (1 - 1e-10 t + 2.25e-5 t^2 has no real root;
 * its rest 1 - 1e-10 t has one at 1e10), and they are not roots.  Weighed
 * over (0, B], B the bound of the rest alone (until issue 33), the rule was
 * circular and lost the roots the leading term makes (1e-16 + t - 4.905 t^2
 * lost 0.2039); never weighed (issue 33, first fix), -4.5 + 3.75 t + 3 t^2 +
 * 3e-30 t^3 kept a cubic term whose only other roots lie near -1e30, and
 * the companion matrix (M2C_METHOD_GSL) lost its root 0.75.  Over (0, K]
 * the leading term is at least twice each term of the opposite sign, so it
 * is negligible only beside a term of its own sign: no root is lost.
 * *bound: K of the polynomial returned (root_bound's value, which
 * solve_normalised's window would compute again), or -1 where none was. */
static int reduce(double c[], int e[], int nz[], int n, double *tmax, int every_root,
                  int emax, double *bound)
{
    for (;;) {
        *bound = -1;
        while (n > 0 && c[n] == 0)
            n--;
        if (n == 0)
            return c[0] == 0 ? -1 : 0;
        if (c[0] == 0) { /* touching now: divide by t */
            for (int i = 0; i < n; i++) {
                c[i] = c[i + 1];
                e[i] = e[i + 1];
                nz[i] = nz[i + 1];
            }
            c[n] = 0;
            e[n] = nz[n] = 0;
            n--;
            continue;
        }
        double T = *tmax;
        if (isinf(T)) {
            double K = root_bound(e, nz, every_root ? NULL : c, n);
            *bound = K;
            T = K > 0 && K < DBL_MAX ? K : INFINITY;
        }
        if (leading_negligible(c, e, nz, n, T, emax)) {
            *tmax = T;
            *bound = -1;
            c[n] = 0;
            e[n] = nz[n] = 0;
            n--;
            continue;
        }
        return n;
    }
}

/* Exponent spread (largest minus smallest exponent of the nonzero
 * coefficients) up to which scaling the largest into [1/2, 1) leaves every
 * coefficient a normal number (>= 2^-1022).  Beyond it: first_root_sliced. */
#define MAX_SPREAD 1021

/* floor(a / b) for b > 0 (C's division truncates toward zero). */
static int floor_div(int a, int b)
{
    int q = a / b;
    return q - (a % b != 0 && a < 0);
}

/* The spread of the exponents e of c[0..n] (load_coefficients) and the largest,
 * *emax; -1 when every coefficient is 0. */
static int spread(const int e[], const int nz[], int n, int *emax)
{
    int hi = INT_MIN, lo = INT_MAX;
    for (int i = 0; i <= n; i++) {
        if (nz[i]) {
            hi = e[i] > hi ? e[i] : hi;
            lo = e[i] < lo ? e[i] : lo;
        }
    }
    *emax = hi;
    return hi == INT_MIN ? -1 : hi - lo;
}

/* The exponents of c[0..n] (finite) and their spread (above). */
static int exponents(const double c[], int n, int e[], int nz[], int *emax)
{
    double copy[MAXN + 1];
    load_coefficients(c, n, copy, e, nz);
    return spread(e, nz, n, emax);
}

/* Scale by sign 2^-E (exact: the spread is at most MAX_SPREAD; sign is +-1)
 * so that max |c_i| (exponent emax) is in [1/2, 1); returns E: the values of
 * p are scaled by 2^-E. */
static int normalise(double c[], int n, int emax, double sign)
{
    int E = emax + 1;
    if (E >= DBL_MIN_EXP && E <= DBL_MAX_EXP - 2) {
        /* multiplying by an exact power of two rounds as ldexp does */
        double f = sign * pow2(-E);
        for (int i = 0; i <= n; i++)
            c[i] *= f;
    } else {
        for (int i = 0; i <= n; i++)
            c[i] = ldexp(sign * c[i], -E);
    }
    return E;
}

/* ------------------------------------------------------------------ */
/* Evaluation                                                           */
/* ------------------------------------------------------------------ */

/* Exponent k such that evaluating a polynomial of degree m at x / 2^k cannot
 * overflow. */
static int scale_exponent(double x, int m)
{
    return fabs(x) <= (m <= 8 ? SAFE_LOW : SAFE_HIGH) ? 0 : ilogb(x) + 1;
}

/* Hardware fma where the build did not assume it (x86 without -mfma, the
 * default): the precise kernels below -- fma Horner and the compensated
 * Horner's error-free products -- are compiled twice, once for the fma
 * instruction (target("fma")) and once plainly, and chosen per call by the
 * CPU (__builtin_cpu_supports: one load and test).  The two give the same
 * bits: fma is correctly rounded whether an instruction or glibc's call,
 * and fma(s, x, -s x) and Dekker's products are both the exact error of
 * s x.  Only speed differs: without the instruction every fma() is a
 * library call, one after the other in a Horner chain (measured:
 * bench/roots_ab.py --sweeps 21, aligned: see docs/performance-log.md).  Plain
 * evaluation stays multiply-then-add everywhere: the answers do not depend
 * on the CPU. */
#if !defined(FP_FAST_FMA) && !defined(M2C_NO_FMA_DISPATCH) && defined(__GNUC__) && \
    (defined(__x86_64__) || defined(__i386__))
#define FMA_DISPATCH 1
#define HW_FMA __attribute__((target("fma"), noinline))
#define ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define FMA_DISPATCH 0
#define ALWAYS_INLINE inline
#endif
/* Inlined in every build where the compiler can be told (ALWAYS_INLINE is
 * a hint where the fma copies do not need it): a body that must become a
 * copy with the degree a constant (bernstein_clear_8). */
#if defined(__GNUC__)
#define FORCE_INLINE inline __attribute__((always_inline))
#else
#define FORCE_INLINE inline
#endif

/* p(x) / 2^(k n) by Horner: fused, with fma (one rounding per step), else
 * multiply-then-add.  With k != 0 the argument and the coefficients are
 * scaled by exact powers of two, so huge x (roots near 1e154 and beyond)
 * evaluate without overflow. */
static ALWAYS_INLINE double horner_core(const double c[], int n, double x, int k,
                                        const int fused)
{
    double acc = c[n];
    if (k == 0) {
        for (int i = n - 1; i >= 0; i--)
            acc = fused ? fma(acc, x, c[i]) : acc * x + c[i];
        return acc;
    }
    double xs = ldexp(x, -k), f = ldexp(1.0, -k), fi = 1.0;
    for (int i = n - 1; i >= 0; i--) {
        fi *= f;
        acc = fused ? fma(acc, xs, c[i] * fi) : acc * xs + c[i] * fi;
    }
    return acc;
}

#if FMA_DISPATCH
static HW_FMA double horner_fma_hw(const double c[], int n, double x, int k)
{
    return horner_core(c, n, x, k, 1);
}
#endif

/* p(x) / 2^(k n) by Horner (horner_core).  precise: with fma.  Without the
 * fma instruction, fma() is a library call per step, which would dominate
 * the solve; so only the last Newton steps of a reported root and the graze
 * check use it, everything else plain multiply-add (two roundings per step:
 * within the gamma_{2n} bound used throughout). */
static double horner(const double c[], int n, double x, int k, int precise)
{
    COUNT_MADDS(n);
    if (!precise)
        return horner_core(c, n, x, k, 0);
#if FMA_DISPATCH
    if (__builtin_cpu_supports("fma"))
        return horner_fma_hw(c, n, x, k);
#endif
    return horner_core(c, n, x, k, 1);
}

/* sum |c_i| |x|^i / 2^(k n): the scale of the Horner rounding error. */
static double horner_abs(const double c[], int n, double x, int k)
{
    COUNT_MADDS(n);
    double ax = fabs(x), acc = fabs(c[n]);
    if (k == 0) { /* (no ldexp: a library call, on every graze check) */
        for (int i = n - 1; i >= 0; i--)
            acc = acc * ax + fabs(c[i]);
        return acc;
    }
    double xs = ldexp(ax, -k), f = ldexp(1.0, -k), fi = 1.0;
    for (int i = n - 1; i >= 0; i--) {
        fi *= f;
        acc = acc * xs + fabs(c[i]) * fi;
    }
    return acc;
}

/* The graze tolerance 2 gamma_{2n} (see header): |p(x)| at most this times
 * sum |c_i| |x|^i is within the rounding noise of evaluating p at x. */
static double noise_factor(int n)
{
#define NOISE(k) (2.0 * (2.0 * (k) * UNIT_ROUNDOFF / (1.0 - 2.0 * (k) * UNIT_ROUNDOFF)))
    static const double table[MAXN + 1] = {
        NOISE(0),  NOISE(1),  NOISE(2),  NOISE(3),  NOISE(4),  NOISE(5),
        NOISE(6),  NOISE(7),  NOISE(8),  NOISE(9),  NOISE(10), NOISE(11),
        NOISE(12), NOISE(13), NOISE(14), NOISE(15), NOISE(16)};
#undef NOISE
    return table[n]; /* constants: a division per solve is not free */
}

/* Is |p(x)| within the rounding noise of its evaluation at x, plus the
 * contact skin (>= 0, in the units of the normalised p)?  noise_holds: the
 * same from v = horner(c, n, x, k, 1), k = scale_exponent(x, n), already
 * computed. */
static int noise_holds(const double c[], int n, double x, int k, double v,
                       double skin)
{
    double sk = k == 0 ? skin : ldexp(skin, -k * n);
    return fabs(v) <= noise_factor(n) * horner_abs(c, n, x, k) + sk;
}

static int within_noise(const double c[], int n, double x, double skin)
{
    int k = scale_exponent(x, n);
    return noise_holds(c, n, x, k, horner(c, n, x, k, 1), skin);
}

/* Sign of p(x) as -1, 0, 1 (scaling does not change it). */
static int sign_at(const double c[], int n, double x, int precise)
{
    double v = horner(c, n, x, scale_exponent(x, n), precise);
    return (v > 0) - (v < 0);
}

/* ------------------------------------------------------------------ */
/* Quadratic                                                            */
/* ------------------------------------------------------------------ */

/* Real roots of a x^2 + b x + c (a != 0), ascending, in r[0..1]; returns 2,
 * or 0 when the discriminant is negative.  *disc gets the discriminant's
 * sign information (0 exactly for a double root).
 * Written with h = -b/2: roots (h +- sqrt(h^2 - a c)) / a.  h^2 - a c is
 * computed as (p - q) + (dp - dq) where dp, dq are the exact rounding errors
 * of p = h*h and q = a*c (FMA): when p and q nearly cancel, p - q is exact
 * (Sterbenz) and the corrections carry the digits (Kahan's case).  The
 * coefficients are first scaled by a power of two so h*h cannot overflow;
 * the larger root comes from h + sign(h) sqrt(.) (no cancellation) and the
 * other from the product of the roots c / a. */
static int quad_roots(double a, double b, double c, double r[2], double *disc)
{
    /* (a != 0: no zero m; every input finite: max and the exponent from the
     * bits, and the scaling a multiplication by an exact power of two,
     * which rounds as ldexp does -- the same values without the four
     * library calls, about a fifth of a quadratic solve's instructions) */
    double m = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
    m = m > fabs(c) ? m : fabs(c);
    int e = exponent_of(m);
    if (-e >= DBL_MIN_EXP - 1 && -e <= DBL_MAX_EXP - 1) {
        double f = pow2(-e);
        a *= f;
        b *= f;
        c *= f;
    } else {
        a = ldexp(a, -e);
        b = ldexp(b, -e);
        c = ldexp(c, -e);
    }
    double h = -0.5 * b;
    double p = h * h, q = a * c;
    double dp = fma(h, h, -p), dq = fma(a, c, -q);
    double d = (p - q) + (dp - dq);
    *disc = d;
    if (d < 0)
        return 0;
    double w = h + copysign(sqrt(d), h);
    double r1, r2;
    if (w == 0) { /* h == 0 and d == 0, so c == 0: double root at 0 */
        r1 = r2 = 0;
    } else {
        r1 = w / a;
        r2 = c / w;
    }
    /* (no NaN here; which zero comes first does not matter: a root must
     * be > lo >= 0) */
    r[0] = r1 < r2 ? r1 : r2;
    r[1] = r1 < r2 ? r2 : r1;
    return 2;
}

/* First root in (lo, tmax] of c0 + c1 t + c2 t^2 (c2 != 0; lo >= 0: 0 but
 * for first_root_sliced). */
NOINLINE static int first_root_quadratic(const double c[3], double lo, double tmax,
                                         double skin, double *t, int *graze)
{
    double r[2], disc;
    if (quad_roots(c[2], c[1], c[0], r, &disc) == 2) {
        for (int i = 0; i < 2; i++) {
            if (r[i] > lo && r[i] <= tmax) {
                *t = r[i];
                *graze = disc == 0;
                return 1;
            }
        }
        return 0;
    }
    if (skin < 0)
        return 0; /* no graze check */
    /* No real root: does the parabola touch 0 within rounding at its vertex? */
    double x = -c[1] / (2 * c[2]);
    if (x > lo && x <= tmax && within_noise(c, 2, x, skin)) {
        *t = x;
        *graze = 1;
        return 1;
    }
    return 0;
}

/* ------------------------------------------------------------------ */
/* Safeguarded Newton on a bracket with one root                       */
/* ------------------------------------------------------------------ */

/* Relative tolerances for roots that are only used to split the window:
 * roots of p' (critical points of p, where the graze check evaluates p:
 * p' = 0 there, so an error d in x changes p by O(d^2) -- negligible at
 * 2^-36) and of the lower derivatives (they only bracket the next level). */
#define TOL_CRITICAL 0x1p-36
#define TOL_LEVEL 0x1p-28

/* Full accuracy: Newton with plain evaluation until the step is below this
 * (relative), then with the precise one (compensated Horner) to about an
 * ulp.  Newton converges quadratically, so after a plain step below 2^-26
 * the iterate is within a few ulps and one precise step finishes it. */
#define PRECISE_FROM 0x1p-26

/* A rejected Newton step this small (relative) in the precise phase means the
 * evaluation is rounding noise: a few ulps, n u kappa for kappa ~ 2. */
#define NOISE_STEP (32 * UNIT_ROUNDOFF)

/* After this many iterations, a Newton step that moves x by more than 2^-10
 * of it in a bracket spanning more than a factor 8 is replaced by a
 * geometric bisection (from lo = 0: hi / 2^64).  Far from every root Newton
 * converges only linearly: it halves x per step on a - b x^2 (from 1e-14 to
 * a root at 1e-150 that is 450 steps, beyond MAX_ITER: it returned 1.5e-71)
 * and takes x to 0.9 x on a degree-10 polynomial from 1e197.  Converging
 * solves take fewer steps than this and are unchanged. */
#define SLOW_AFTER 16

/* Bisection point of [lo, hi] (0 <= lo < hi): geometric when the bracket
 * spans more than a factor 8, so roots near 0 (1e-12) are reached in a few
 * dozen steps and to relative, not absolute, accuracy. */
static double split_point(double lo, double hi)
{
    if (lo == 0)
        return hi * 0x1p-10;
    if (hi > 8 * lo)
        return sqrt(lo) * sqrt(hi);
    return lo + 0.5 * (hi - lo);
}

/* P(x) to about an ulp of |P(x)| plus gamma_{2m}^2 sum |P_i| |x|^i:
 * compensated Horner (Graillat, Langlois & Louvet 2005), so the root comes
 * out correct to about an ulp unless its condition number nears 1/u (plain or
 * fma Horner leave m u kappa: 1e-13 at kappa 1e3).  The error-free product
 * is fma(s, x, -s x) where fma is an instruction (hw: -mfma, or the CPU's
 * at run time, FMA_DISPATCH above), else Dekker's splitting (without the
 * instruction, fma() is a library call per step); both give the exact
 * error, so the same bits.  Needs |x| and the partial sums far below 2^996
 * (the splitting): true for |x| <= FAST_LIMIT. */
#ifdef FP_FAST_FMA
#define FMA_BUILT_IN 1
#else
#define FMA_BUILT_IN 0
#endif

/* Dekker's splitting: v = *hi + *lo exactly, each with at most 26 bits. */
static inline void dekker_split(double v, double *hi, double *lo)
{
    const double split = 134217729.0; /* 2^27 + 1 */
    double t = split * v;
    *hi = t - (t - v);
    *lo = v - *hi;
}

static ALWAYS_INLINE void compensated_step(double *s, double *c, double x, double xh,
                                           double xl, double Pi, const int hw)
{
    double p = *s * x, pe;
    if (hw) {
        pe = fma(*s, x, -p); /* s x = p + pe exactly */
    } else {
        double sh, sl;
        dekker_split(*s, &sh, &sl);
        pe = ((sh * xh - p) + sh * xl + sl * xh) + sl * xl;
    }
    double sn = p + Pi, bb = sn - p;
    double se = (p - (sn - bb)) + (Pi - bb); /* p + P_i = sn + se */
    *c = *c * x + (pe + se);
    *s = sn;
}

static ALWAYS_INLINE double compensated_core(const double P[], int m, double x,
                                             const int hw)
{
    double xh = 0, xl = 0;
    if (!hw)
        dekker_split(x, &xh, &xl);
    double s = P[m], c = 0;
    for (int i = m - 1; i >= 0; i--)
        compensated_step(&s, &c, x, xh, xl, P[i], hw);
    return s + c;
}

/* The same, and *slope = D(x) (D of degree m - 1, m >= 1) by plain Horner
 * in the same loop: a Newton step's two chains side by side, where one
 * after the other they waited on each other (measured below,
 * value_and_slope). */
static ALWAYS_INLINE double compensated_slope_core(const double P[], const double D[],
                                                   int m, double x, double *slope,
                                                   const int hw)
{
    double xh = 0, xl = 0;
    if (!hw)
        dekker_split(x, &xh, &xl);
    double s = P[m], c = 0, df = D[m - 1];
    for (int i = m - 1; i >= 1; i--) {
        compensated_step(&s, &c, x, xh, xl, P[i], hw);
        df = df * x + D[i - 1];
    }
    compensated_step(&s, &c, x, xh, xl, P[0], hw);
    *slope = df;
    return s + c;
}

#if FMA_DISPATCH
static HW_FMA double compensated_hw(const double P[], int m, double x)
{
    return compensated_core(P, m, x, 1);
}

static HW_FMA double compensated_slope_hw(const double P[], const double D[], int m,
                                          double x, double *slope)
{
    return compensated_slope_core(P, D, m, x, slope, 1);
}
#endif

static double horner_compensated(const double P[], int m, double x)
{
    COUNT_MADDS(10 * m); /* about 21 flops a step */
#if FMA_DISPATCH
    if (__builtin_cpu_supports("fma"))
        return compensated_hw(P, m, x);
#endif
    return compensated_core(P, m, x, FMA_BUILT_IN);
}

/* (uncounted: for an evaluation done ahead of its use, counted there) */
static double compensated_slope_ahead(const double P[], const double D[], int m,
                                      double x, double *slope)
{
#if FMA_DISPATCH
    if (__builtin_cpu_supports("fma"))
        return compensated_slope_hw(P, D, m, x, slope);
#endif
    return compensated_slope_core(P, D, m, x, slope, FMA_BUILT_IN);
}

static double compensated_with_slope(const double P[], const double D[], int m,
                                     double x, double *slope)
{
    COUNT_MADDS(10 * m);
    return compensated_slope_ahead(P, D, m, x, slope);
}

/* What scan_pieces and touch_point read on a touch's interval (lo, hi],
 * its one critical point b from touch_critical: p(b) by fma Horner (vb),
 * compensated (pb), sum |p_i| b^i (ab: the graze check's scale), p(hi) by
 * fma Horner (vhi), and p'(b) compensated with p''(b) plain (dv, ddv:
 * touch_point's Newton step) -- five evaluations' chains in one loop, side
 * by side, where scan_pieces ran them one after the other, each behind the
 * branch before it.  Each chain's operations are those of horner,
 * horner_abs, horner_compensated and compensated_with_slope in the same
 * order: the same values, bit for bit (tests/runtime/test_fma_dispatch.py
 * checks the copies; the answers, tests/runtime/test_touch_critical.py).
 * For b and hi that need no scaling (scale_exponent 0) only. */
typedef struct {
    double vb, pb, ab, vhi, dv, ddv;
} TouchValues;

static ALWAYS_INLINE void touch_values_core(const double c[], const double D1[],
                                            const double D2[], int n, double b,
                                            double hi, TouchValues *tv, const int hw)
{
    double bh = 0, bl = 0;
    if (!hw)
        dekker_split(b, &bh, &bl);
    int m = n - 1; /* p' = D1, of degree m; p'' = D2 */
    double vb = c[n], vhi = c[n], ab = fabs(c[n]), axb = fabs(b);
    double s = c[n], e = 0, s1 = D1[m], e1 = 0, df = D2[m - 1];
    for (int i = n - 1; i >= 0; i--) {
        vb = fma(vb, b, c[i]);
        vhi = fma(vhi, hi, c[i]);
        ab = ab * axb + fabs(c[i]);
        compensated_step(&s, &e, b, bh, bl, c[i], hw);
        if (i < m) {
            compensated_step(&s1, &e1, b, bh, bl, D1[i], hw);
            if (i >= 1)
                df = df * b + D2[i - 1];
        }
    }
    tv->vb = vb;
    tv->pb = s + e;
    tv->ab = ab;
    tv->vhi = vhi;
    tv->dv = s1 + e1;
    tv->ddv = df;
}

#if FMA_DISPATCH
static HW_FMA void touch_values_hw(const double c[], const double D1[], const double D2[],
                                   int n, double b, double hi, TouchValues *tv)
{
    touch_values_core(c, D1, D2, n, b, hi, tv, 1);
}
#endif

static void touch_values(const double c[], const double D1[], const double D2[], int n,
                         double b, double hi, TouchValues *tv)
{
#if FMA_DISPATCH
    if (__builtin_cpu_supports("fma")) {
        touch_values_hw(c, D1, D2, n, b, hi, tv);
        return;
    }
#endif
    touch_values_core(c, D1, D2, n, b, hi, tv, FMA_BUILT_IN);
}

/* P(x) / 2^(k m) (precise: compensated for k = 0, with fma otherwise) and
 * P'(x) / 2^(k (m-1)) = D(x) / ..., as horner() scales them (so the Newton
 * step is 2^k times their ratio); *size gets sum |P_i| |x|^i / 2^(k m), the
 * scale of the rounding error -- but not when precise with k = 0, where
 * refine_root does not look at it (0 then).  For k = 0 in one loop:
 * independent chains (precisely: compensated_with_slope's, without the plain
 * value and size it used to compute first and drop -- measured with
 * bench/roots_ab.py: generic octics 0.989 of the instructions, 0.96 of
 * the time at the median and 0.99 in the mean; collision polynomials
 * 0.986; the same answers, bit for bit). */
static double value_and_slope(const double P[], const double D[], int m,
                              double x, int k, int precise, double *slope,
                              double *size)
{
    if (k != 0) {
        *slope = horner(D, m - 1, x, k, 0);
        *size = horner_abs(P, m, x, k);
        return horner(P, m, x, k, precise);
    }
    COUNT_MADDS(3 * m - 1); /* (the cost model's count, either way) */
    if (precise) {
        *size = 0;
        return compensated_with_slope(P, D, m, x, slope);
    }
    double f = P[m], df = D[m - 1], ax = fabs(x), sz = fabs(P[m]);
    f = f * x + P[m - 1];
    sz = sz * ax + fabs(P[m - 1]);
    for (int i = m - 2; i >= 0; i--) {
        df = df * x + D[i];
        sz = sz * ax + fabs(P[i]);
        f = f * x + P[i];
    }
    *slope = df;
    *size = sz;
    return f;
}

/* The root of P (degree m, derivative D) in (lo, hi), where P changes sign
 * exactly once (slo = sign of P(lo), nonzero): P monotone there, or the root
 * isolated by Budan-Fourier counts.  x0 in (lo, hi) is the first guess.
 * tol > 0: stop once the bracket or the Newton step is below tol relative,
 * or once a Newton step that leaves the bracket is below NOISE_STEP: x is
 * then the root to within the noise of P's plain value (a sign from the
 * noise had moved a bracket end to x itself).  That step used to go to
 * bisection, which crept from the far end until the bracket was below tol
 * (about 5 steps on every touch of bench/roots.py's grazes, and touches up
 * to 1.5e-11 from their critical points: tests/runtime/test_touch_point.py).
 * tol == 0: full relative double accuracy: plain evaluation until the step
 * (or the bracket) is below PRECISE_FROM or the value is within its rounding
 * bound (so the bracket ends always have the right sign: the precise phase
 * can only sharpen them), then the precise one (compensated Horner; fma
 * Horner for scaled arguments) until the step is a few ulps -- usually a
 * single step -- or until Newton, a few ulps from the root, stops
 * converging: there the evaluation is all rounding noise and no point is
 * better than x (bisecting the whole bracket instead would wander away and
 * back).  tol == PRECISE_NOW: the same, but precise from the first step,
 * for an x0 near converged (the guess's Laguerre iterate, its last step
 * below GUESS_DONE, cubic convergence): a plain step there only confirmed
 * it (measured with the step below PRECISE_FROM then:
 * bench/roots_ab.py --instructions, generic octics 0.987, collision
 * polynomials 0.978; timed 0.97-0.98; the same answers, bit for bit). */
#define PRECISE_NOW (-1.0)
/* first: P(x0) and P'(x0) as value_and_slope gives them precisely (k = 0),
 * computed ahead by the caller, for the first step (else NULL). */
static double refine_root_from(const double P[], const double D[], int m,
                               double lo, double hi, int slo, double tol, double x0,
                               const double *first)
{
    double x = x0;
    double step = hi - lo, step_old = step;
    int precise = tol < 0;
    tol = tol < 0 ? 0 : tol;
    double stop = tol > 0 ? tol : precise ? 2 * UNIT_ROUNDOFF : PRECISE_FROM;
    for (int it = 0; it < MAX_ITER; it++) {
        COUNT(precise ? 5 : 4);
        int k = scale_exponent(x, m);
        double df, size, f;
        if (it == 0 && first != NULL) { /* (value_and_slope's, precise, k = 0) */
            COUNT_MADDS(3 * m - 1 + 10 * m);
            f = first[0];
            df = first[1];
            size = 0;
        } else {
            f = value_and_slope(P, D, m, x, k, precise, &df, &size);
        }
        if (tol == 0 && !precise && fabs(f) <= noise_factor(m) * size) {
            /* plain evaluation cannot tell the sign here: look again,
             * precisely (and keep the bracket ends to trusted signs) */
            precise = 1;
            stop = 2 * UNIT_ROUNDOFF;
            continue;
        }
        if (f == 0)
            return x;
        if ((f > 0) == (slo > 0))
            lo = x;
        else
            hi = x;
        if (hi - lo <= 2 * DBL_EPSILON * hi || (tol > 0 && hi - lo <= tol * hi)) {
            if (precise || tol > 0)
                return x;
            precise = 1; /* the plain signs closed the bracket: check them */
            stop = 2 * UNIT_ROUNDOFF;
            continue;
        }
        if (tol == 0 && hi - lo <= PRECISE_FROM * hi) {
            precise = 1;
            stop = 2 * UNIT_ROUNDOFF;
        }
        double xn = x - (k ? ldexp(f / df, k) : f / df);
        double s = x - xn;
        int slow = it >= SLOW_AFTER && (lo == 0 || hi > 8 * lo) &&
                   fabs(s) > 0x1p-10 * fabs(xn);
        /* Newton must stay inside the bracket and at least halve the step
         * before last; otherwise bisect (rtsafe's rule). */
        if (!(xn > lo && xn < hi) || fabs(s) > 0.5 * fabs(step_old) || slow) {
            if ((precise || tol > 0) && fabs(s) <= NOISE_STEP * fabs(x))
                return x;
            double far = hi * 0x1p-64;
            xn = slow && lo == 0 && far > DBL_MIN ? far : split_point(lo, hi);
            s = x - xn;
        }
        step_old = step;
        step = s;
        if (fabs(s) <= stop * fabs(xn) || (precise && fabs(s) <= NOISE_STEP * fabs(x))) {
            /* converged; a precise Newton step of a few ulps lands within
             * O(step^2) of where the precise evaluation puts the root */
            if (precise || tol > 0)
                return xn;
            precise = 1;   /* the last step(s), precisely */
            stop = 2 * UNIT_ROUNDOFF;
        }
        x = xn;
    }
    return x;
}

static double refine_root(const double P[], const double D[], int m,
                          double lo, double hi, int slo, double tol, double x0)
{
    return refine_root_from(P, D, m, lo, hi, slo, tol, x0, NULL);
}

/* ------------------------------------------------------------------ */
/* Budan-Fourier isolation                                              */
/* ------------------------------------------------------------------ */
/*
 * For p with p(0) > 0 the first event in (0, T] is a root, or a touch: a
 * point where p comes within the rounding noise of 0 without crossing (the
 * graze check).  Both lie where the lower envelope
 *     q(x) = p(x) - 2 gamma_{2n} sum |p_i| x^i      (q_i = p_i - e |p_i|)
 * is <= 0; q(0) > 0, so if q has no root in (a, b] nothing happens there.
 * (Without the graze check, q = p.)
 *
 * Budan-Fourier: the number of roots in (a, b], counted with multiplicity,
 * is at most V(a) - V(b) and has its parity, where V(x) is the number of
 * sign changes of the Taylor coefficients at x (zeros skipped).  V(0) is read
 * off the coefficients; V(x) needs a Taylor shift, whose signs are trusted
 * only when each coefficient exceeds its rounding bound.  So:
 *   q count 0               nothing in (a, b]: move right;
 *   p count 1 and q count 1 exactly one simple root of p, and any dip of p
 *                           into the noise before it stays in the noise up
 *                           to the root (else q would have 3 roots): polish
 *                           it by safeguarded Newton;
 *   otherwise               split (a, b] and look at the left half first.
 * Splits are capped; double roots (touches) and tight clusters never give
 * count 1 and go to the derivative method on the unresolved interval
 * (everything before it is cleared); if it finds nothing there, the
 * isolation goes on to the right.
 */

/* Windows beyond this go straight to the derivative method (which scales
 * its evaluations): up to it, Horner and the Taylor shift of normalised
 * coefficients cannot overflow (9 * 2^(8 * 100) * 2^8 < DBL_MAX at degree
 * <= 8, 17 * 2^(16 * 56) * 2^14 above). */
#define FAST_LIMIT_LOW 0x1p100
#define FAST_LIMIT_HIGH 0x1p56

/* Caps on the bisection: number of splits, and the relative width below
 * which an interval that still holds two or more roots is left to the
 * derivative method; and the relative width up to which one holding two
 * by both counts goes to it at once (isolate_first_root: measured, 1/2
 * and 1/8 did as well on grazes, with more cost where it finds nothing). */
#define MAX_SPLITS 40
#define SPLIT_NEWTON 2.0
#define MIN_WIDTH 0x1p-20
#define EARLY_WIDTH 0.25
/* Half-width (relative) of the interval around a touch found by the guess
 * that goes to the derivative method (isolate_first_root). */
#define TOUCH_WIDTH 0x1p-10

/* Sign changes in v[0..n], zeros skipped (branch-free: the signs are
 * data, and mispredictions would cost more than the loop). */
static int sign_changes(const double v[], int n)
{
    int count = 0, last = 0;
    for (int i = 0; i <= n; i++) {
        int s = (v[i] > 0) - (v[i] < 0);
        count += s * last < 0;
        last = s != 0 ? s : last;
    }
    return count;
}

/* Sign changes in v[0..n] when no entry is 0 or NaN (every sign certain:
 * point_at, bernstein_test): from the sign bits alone, the same count as
 * sign_changes with a third of its instructions (measured with
 * bench/roots_ab.py: generic octics 0.944 of the instructions, grazes 0.947,
 * quartics 0.965; timed --sweeps 15, aligned, 0.96-0.97 of the time, grazes
 * 1.00 at the median and 0.97 in the mean; the same answers, bit for bit). */
static int changes_certain(const double v[], int n)
{
    uint64_t prev, b;
    memcpy(&prev, &v[0], sizeof prev);
    int count = 0;
    for (int i = 1; i <= n; i++) {
        memcpy(&b, &v[i], sizeof b);
        count += (int)((b ^ prev) >> 63);
        prev = b;
    }
    return count;
}

/* The Taylor coefficients of p at x are the values at x of the polynomials
 * p^(k)/k!, whose coefficients C(j+k, k) p_{j+k} are tabulated once per
 * solve (tk[k][j]; ta the same for |p_i|, whose Taylor coefficients bound
 * the rounding errors and give the envelope: q^(k)/k! = p^(k)/k! - e |p|^(k)/k!
 * exactly).  Evaluating the n + 1 of them by Horner side by side keeps the
 * multiply-adds independent; the textbook synthetic division is one long
 * dependent chain, three times slower here. */
typedef struct {
    double tk[MAXN + 1][MAXN + 1], ta[MAXN + 1][MAXN + 1];
    double e;    /* envelope factor: 2 gamma_{2n} with the graze check, else 0 */
    double skin; /* contact skin (normalised units), subtracted from q_0 */
    int top;     /* the degree up to which the tables are filled: 4 or 8 */
} Taylor;

/* BINOM[k][j] = C(j + k, k) */
static const double BINOM[MAXN + 1][MAXN + 1] = {
    {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1},
    {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 0},
    {1, 3, 6, 10, 15, 21, 28, 36, 45, 55, 66, 78, 91, 105, 120, 0, 0},
    {1, 4, 10, 20, 35, 56, 84, 120, 165, 220, 286, 364, 455, 560, 0, 0, 0},
    {1, 5, 15, 35, 70, 126, 210, 330, 495, 715, 1001, 1365, 1820, 0, 0, 0, 0},
    {1, 6, 21, 56, 126, 252, 462, 792, 1287, 2002, 3003, 4368, 0, 0, 0, 0, 0},
    {1, 7, 28, 84, 210, 462, 924, 1716, 3003, 5005, 8008, 0, 0, 0, 0, 0, 0},
    {1, 8, 36, 120, 330, 792, 1716, 3432, 6435, 11440, 0, 0, 0, 0, 0, 0, 0},
    {1, 9, 45, 165, 495, 1287, 3003, 6435, 12870, 0, 0, 0, 0, 0, 0, 0, 0},
    {1, 10, 55, 220, 715, 2002, 5005, 11440, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {1, 11, 66, 286, 1001, 3003, 8008, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {1, 12, 78, 364, 1365, 4368, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {1, 13, 91, 455, 1820, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {1, 14, 105, 560, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {1, 15, 120, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {1, 16, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
};

static void taylor_table(const double p[], int n, double e, double skin,
                         Taylor *tb)
{
    for (int k = 0; k <= n; k++) {
        for (int j = 0; j + k <= n; j++) {
            tb->tk[k][j] = BINOM[k][j] * p[j + k];
            tb->ta[k][j] = fabs(tb->tk[k][j]);
        }
    }
    /* zeros up to degree 8, which point_at's written-out form reads; in
     * the quartics' copy up to degree 4, and point_at's form for degree 4
     * reads no more (told by top: whether n is a constant here is the
     * compiler's to decide at each place, and Clang's answers differ
     * between two places of one copy) */
    tb->top = CONSTANT_AT_MOST(n, 4) ? 4 : 8;
    for (int k = 0; k <= tb->top; k++)
        for (int j = n + 1 - k > 0 ? n + 1 - k : 0; j + k <= tb->top; j++)
            tb->tk[k][j] = tb->ta[k][j] = 0;
    tb->e = e;
    tb->skin = skin;
}

/* What is known at a point x of the window: Budan-Fourier sign changes of p
 * and q, p(x), and q's Taylor coefficients at x with bounds on their errors
 * (for the exclusion test). */
typedef struct {
    double x, px, dpx; /* x, p(x), p'(x) */
    int vp, vq;
    double pt[MAXN + 1], qt[MAXN + 1], tol[MAXN + 1];
} Point;

/* The point 0: the coefficients themselves (q_i = p_i - e |p_i| has the sign
 * of p_i, but for q_0 less a positive skin; its rounding is in tol). */
static void point_at_zero(const double p[], int n, double e, double skin,
                          Point *pt)
{
    pt->x = 0;
    pt->px = p[0];
    pt->dpx = p[1];
    /* i = 0 apart: gcc (-Wmaybe-uninitialized) cannot see that n >= 1 */
    pt->pt[0] = p[0];
    pt->qt[0] = p[0] - e * fabs(p[0]);
    pt->tol[0] = DBL_EPSILON * fabs(p[0]);
    int zero = 0;
    for (int i = 1; i <= n; i++) {
        pt->pt[i] = p[i];
        pt->qt[i] = p[i] - e * fabs(p[i]);
        pt->tol[i] = DBL_EPSILON * fabs(p[i]);
        zero |= p[i] == 0;
    }
    /* (p[0] > 0; without zeros, from the sign bits) */
    pt->vp = zero ? sign_changes(p, n) : changes_certain(p, n);
    if (skin > 0) {
        pt->qt[0] -= skin;
        pt->tol[0] += DBL_EPSILON * skin;
        pt->vq = sign_changes(pt->qt, n);
    } else {
        pt->vq = pt->vp;
    }
}

/* The point x > 0.  Each Taylor coefficient is a sum over paths of at most
 * 2n + 2 roundings (the tabulated product, then Horner), so gamma_{2n+2}
 * times the same sum on |p_i| bounds its error; we take twice that (which
 * also covers forming q's from p's), plus a term for underflow.  Returns 0
 * when a sign is not certain: the counts would not be trustworthy. */
static int point_at(const Taylor *tb, int n, double x, Point *pt)
{
    COUNT(6);
    COUNT_MADDS((n + 1) * (n + 2)); /* two triangles of n(n+1)/2 + (n+1) */
    double a[MAXN + 1] = {0}, s[MAXN + 1] = {0};
#define TS(k, d)                               \
    a##k = a##k * x + tb->tk[k][d];            \
    s##k = s##k * x + tb->ta[k][d]
    if (n <= 4 && tb->top == 4) {
        /* the same for degree 4 in the quartics' copy (taylor_table): a
         * third of degree 8's products */
        double a0 = 0, a1 = 0, a2 = 0, a3 = 0, a4 = 0;
        double s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0;
        TS(0, 4);
        TS(0, 3); TS(1, 3);
        TS(0, 2); TS(1, 2); TS(2, 2);
        TS(0, 1); TS(1, 1); TS(2, 1); TS(3, 1);
        TS(0, 0); TS(1, 0); TS(2, 0); TS(3, 0); TS(4, 0);
        a[0] = a0; a[1] = a1; a[2] = a2; a[3] = a3; a[4] = a4;
        s[0] = s0; s[1] = s1; s[2] = s2; s[3] = s3; s[4] = s4;
    } else if (n <= 8) {
        /* written out for degree 8 (the table is 0 above degree n, and 0 x +
         * 0 = 0 for x > 0: the same values as the loop below, bit for bit):
         * the loop's bounds vary with n, and its control and memory traffic
         * cost more than the arithmetic */
        double a0 = 0, a1 = 0, a2 = 0, a3 = 0, a4 = 0, a5 = 0, a6 = 0, a7 = 0, a8 = 0;
        double s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0, s8 = 0;
        TS(0, 8);
        TS(0, 7); TS(1, 7);
        TS(0, 6); TS(1, 6); TS(2, 6);
        TS(0, 5); TS(1, 5); TS(2, 5); TS(3, 5);
        TS(0, 4); TS(1, 4); TS(2, 4); TS(3, 4); TS(4, 4);
        TS(0, 3); TS(1, 3); TS(2, 3); TS(3, 3); TS(4, 3); TS(5, 3);
        TS(0, 2); TS(1, 2); TS(2, 2); TS(3, 2); TS(4, 2); TS(5, 2); TS(6, 2);
        TS(0, 1); TS(1, 1); TS(2, 1); TS(3, 1); TS(4, 1); TS(5, 1); TS(6, 1); TS(7, 1);
        TS(0, 0); TS(1, 0); TS(2, 0); TS(3, 0); TS(4, 0); TS(5, 0); TS(6, 0); TS(7, 0);
        TS(8, 0);
        a[0] = a0; a[1] = a1; a[2] = a2; a[3] = a3; a[4] = a4; a[5] = a5; a[6] = a6;
        a[7] = a7; a[8] = a8;
        s[0] = s0; s[1] = s1; s[2] = s2; s[3] = s3; s[4] = s4; s[5] = s5; s[6] = s6;
        s[7] = s7; s[8] = s8;
    } else {
        for (int d = n; d >= 0; d--) {
            for (int k = 0; k <= n - d; k++) {
                a[k] = a[k] * x + tb->tk[k][d];
                s[k] = s[k] * x + tb->ta[k][d];
            }
        }
    }
#undef TS
    double rel = 8.0 * (n + 1) * UNIT_ROUNDOFF;
    /* underflow adds at most 2^-1075 per operation: far below DBL_MIN (a
     * normal number: arithmetic on subnormals is slow) */
    double tiny = DBL_MIN;
    for (int k = 0; k <= n; k++) {
        double b = a[k] - tb->e * s[k];
        double tol = rel * s[k] + tiny;
        if (k == 0 && tb->skin > 0) {
            b -= tb->skin;
            tol += rel * tb->skin;
        }
        if (!(fabs(a[k]) > tol && fabs(b) > tol))
            return 0; /* also catches NaN/Inf */
        pt->pt[k] = a[k];
        pt->qt[k] = b;
        pt->tol[k] = tol;
        s[k] = b; /* q's Taylor coefficients, for the count */
    }
    pt->x = x;
    pt->px = a[0];
    pt->dpx = a[1];
    pt->vp = changes_certain(a, n); /* (every |a_k|, |b_k| > tol > 0 above) */
    pt->vq = changes_certain(s, n);
    return 1;
}

/* Is q > 0 on [x, x + w] (dir = 1) or [x - w, x] (dir = -1), x the point pt?
 * With lower bounds L_k of the Taylor coefficients in the direction dir,
 * q >= L_0 - sum_{L_k < 0} |L_k| w^k there.  (The computed sum is within
 * (1 + gamma_{2n}) of the exact one.)  Clears small intervals that Budan-
 * Fourier cannot: V(a) - V(b) stays 2 on any interval around a point where
 * a derivative vanishes and two sign changes are lost, root or not.
 * Failing that, to second order: for 0 <= h <= w,
 *     q >= L_0 + L_1 h + (L_2 - sum_{k>=3, L_k < 0} |L_k| w^(k-2)) h^2,
 * and when that quadratic's h^2 coefficient is positive its minimum over
 * [0, w] is closed-form.  Near a complex pair u +- iv close to the axis q
 * behaves like A ((x - u)^2 + v^2): the first-order test needs intervals of
 * width about v^2 / |u - x|, this one clears the pair's whole neighbourhood
 * in one step (bisections near such pairs were most of the cost of "no root,
 * complex roots near the window").  bounds_positive: the same from q's
 * Taylor coefficients and their error bounds as arrays. */
static int bounds_positive(const double qt[], const double tol[], int n,
                           double w, int dir)
{
    COUNT_MADDS(n);
    double rel = 4.0 * (n + 1) * UNIT_ROUNDOFF;
    double r3 = 0; /* sum_{k>=3} max(0, -L_k) w^(k-3) */
    for (int k = n; k >= 3; k--) {
        double lk = (dir < 0 && k % 2 ? -qt[k] : qt[k]) - tol[k];
        r3 = r3 * w + (lk < 0 ? -lk : 0);
    }
    double lk[3];
    for (int k = 0; k <= 2 && k <= n; k++)
        lk[k] = (dir < 0 && k % 2 ? -qt[k] : qt[k]) - tol[k];
    double neg = r3;
    for (int k = n < 2 ? n : 2; k >= 1; k--)
        neg = neg * w + (lk[k] < 0 ? -lk[k] : 0);
    neg *= w;
    double L0 = lk[0];
    if (L0 > neg + rel * neg)
        return 1;
    if (n < 2)
        return 0;
    double L1 = lk[1], L2 = lk[2] - r3 * w * (1 + rel);
    if (!(L2 > 0))
        return 0;
    double h = -L1 / (2 * L2); /* where L0 + L1 h + L2 h^2 is least */
    h = h < 0 ? 0 : (h > w ? w : h);
    double m = L0 + h * (L1 + h * L2);
    double size = fabs(L0) + h * (fabs(L1) + h * L2);
    return m > 2 * rel * size;
}

static int clearly_positive(const Point *pt, int n, double w, int dir)
{
    return bounds_positive(pt->qt, pt->tol, n, w, dir);
}

/* The Bernstein coefficients of p and q on [x, x + w] (x = pt->x), from their
 * Taylor coefficients at x: with t_k the k-th of them and s = (y - x) / w,
 * the j-th coefficient is sum_{k <= j} C(j, k) t_k w^k / C(n, k) (formed by
 * binomial_sums).  Descartes' rule in this basis (the number of sign changes
 * bounds the roots in (x, x + w) and has their parity) is never weaker than
 * Budan-Fourier's V(x) - V(x + w) and is often much sharper: an interval
 * that Budan-Fourier sees two roots in, on account of a complex pair
 * nearby, is typically cleared, and one it must split is typically found to
 * hold a single root -- without the Taylor shift at a new point that a split
 * costs ((n + 1)(n + 2) multiply-adds).  Each coefficient's sign is trusted
 * only beyond a bound on its error: the Taylor coefficient's own (tol), and
 * the conversion's (w^k and the two products: k + 3 roundings; the sums: n),
 * taken twice.  Returns BERN_CLEAR when q's coefficients are all certainly
 * positive (q > 0 on the interval: nothing in it), BERN_ONE when every sign
 * of p and q is certain and each changes sign once (so, as with counts 1 and
 * 1 above, exactly one simple root of p and nothing before it but noise),
 * else BERN_UNKNOWN.  *pend gets p(x + w) (the last coefficient) with
 * BERN_ONE. */
#define BERN_UNKNOWN 0
#define BERN_CLEAR 1
#define BERN_ONE 2
/* q's Bernstein coefficients on an interval, a bound on their errors, and
 * whether their signs are certain with an even number of changes. */
typedef struct {
    double b[MAXN + 1];
    double err;
    int even;
} BernQ;

/* Round `from` of the running sums on b0..b8, each entry j >= from adding
 * its left neighbour, j descending: the upper entries, then the lower. */
#define SUMS_HIGH(from)                                                    \
    do {                                                                   \
        if (8 >= from) b8 += b7;                                           \
        if (7 >= from) b7 += b6;                                           \
        if (6 >= from) b6 += b5;                                           \
        if (5 >= from) b5 += b4;                                           \
    } while (0)
#define SUMS_LOW(from)                                                     \
    do {                                                                   \
        if (4 >= from) b4 += b3;                                           \
        if (3 >= from) b3 += b2;                                           \
        if (2 >= from) b2 += b1;                                           \
        if (1 >= from) b1 += b0;                                           \
    } while (0)

/* b_j = sum_{k <= j} C(j, k) a_k, j = 0..n, in place: n rounds of running
 * sums (round r adds each entry j >= r's left neighbour, j descending), so
 * additions only.  Up to degree 8 written out in full for 9 entries (the
 * entries above n only take sums of those below and never feed back, so the
 * entries 0..n are the same as the loop's, bit for bit): with loop bounds
 * that vary with n the compiler keeps loop control and memory traffic in
 * the way, measured 5 times slower. */
static void binomial_sums(double a[], int n)
{
    if (CONSTANT_AT_MOST(n, 4)) {
        /* the same for 5 entries in the quartics' copy: 10 sums, not 36 */
        double b0 = a[0], b1 = a[1], b2 = a[2], b3 = a[3], b4 = a[4];
        SUMS_LOW(1);
        SUMS_LOW(2);
        SUMS_LOW(3);
        SUMS_LOW(4);
        a[0] = b0;
        a[1] = b1;
        a[2] = b2;
        a[3] = b3;
        a[4] = b4;
        return;
    }
    if (n <= 8) {
        double b0 = a[0], b1 = a[1], b2 = a[2], b3 = a[3], b4 = a[4], b5 = a[5],
               b6 = a[6], b7 = a[7], b8 = a[8];
#define ROUND(from)                                                        \
    do {                                                                   \
        SUMS_HIGH(from);                                                   \
        SUMS_LOW(from);                                                    \
    } while (0)
        ROUND(1);
        ROUND(2);
        ROUND(3);
        ROUND(4);
        ROUND(5);
        ROUND(6);
        ROUND(7);
        ROUND(8);
#undef ROUND
        a[0] = b0;
        a[1] = b1;
        a[2] = b2;
        a[3] = b3;
        a[4] = b4;
        a[5] = b5;
        a[6] = b6;
        a[7] = b7;
        a[8] = b8;
        return;
    }
    for (int r = 1; r <= n; r++)
        for (int j = n; j >= r; j--)
            a[j] += a[j - 1];
}
#undef SUMS_HIGH
#undef SUMS_LOW

static int bernstein_test(const Point *pt, int n, double w, double *pend,
                          BernQ *qb)
{
    static const double INV_BINOM[MAXN + 1][MAXN + 1] = {
        {1},
        {1, 1},
        {1, 1.0 / 2, 1},
        {1, 1.0 / 3, 1.0 / 3, 1},
        {1, 1.0 / 4, 1.0 / 6, 1.0 / 4, 1},
        {1, 1.0 / 5, 1.0 / 10, 1.0 / 10, 1.0 / 5, 1},
        {1, 1.0 / 6, 1.0 / 15, 1.0 / 20, 1.0 / 15, 1.0 / 6, 1},
        {1, 1.0 / 7, 1.0 / 21, 1.0 / 35, 1.0 / 35, 1.0 / 21, 1.0 / 7, 1},
        {1, 1.0 / 8, 1.0 / 28, 1.0 / 56, 1.0 / 70, 1.0 / 56, 1.0 / 28, 1.0 / 8, 1},
        {1, 1.0 / 9, 1.0 / 36, 1.0 / 84, 1.0 / 126, 1.0 / 126, 1.0 / 84, 1.0 / 36, 1.0 / 9, 1},
        {1, 1.0 / 10, 1.0 / 45, 1.0 / 120, 1.0 / 210, 1.0 / 252, 1.0 / 210, 1.0 / 120, 1.0 / 45,
         1.0 / 10, 1},
        {1, 1.0 / 11, 1.0 / 55, 1.0 / 165, 1.0 / 330, 1.0 / 462, 1.0 / 462, 1.0 / 330, 1.0 / 165,
         1.0 / 55, 1.0 / 11, 1},
        {1, 1.0 / 12, 1.0 / 66, 1.0 / 220, 1.0 / 495, 1.0 / 792, 1.0 / 924, 1.0 / 792, 1.0 / 495,
         1.0 / 220, 1.0 / 66, 1.0 / 12, 1},
        {1, 1.0 / 13, 1.0 / 78, 1.0 / 286, 1.0 / 715, 1.0 / 1287, 1.0 / 1716, 1.0 / 1716,
         1.0 / 1287, 1.0 / 715, 1.0 / 286, 1.0 / 78, 1.0 / 13, 1},
        {1, 1.0 / 14, 1.0 / 91, 1.0 / 364, 1.0 / 1001, 1.0 / 2002, 1.0 / 3003, 1.0 / 3432,
         1.0 / 3003, 1.0 / 2002, 1.0 / 1001, 1.0 / 364, 1.0 / 91, 1.0 / 14, 1},
        {1, 1.0 / 15, 1.0 / 105, 1.0 / 455, 1.0 / 1365, 1.0 / 3003, 1.0 / 5005, 1.0 / 6435,
         1.0 / 6435, 1.0 / 5005, 1.0 / 3003, 1.0 / 1365, 1.0 / 455, 1.0 / 105, 1.0 / 15, 1},
        {1, 1.0 / 16, 1.0 / 120, 1.0 / 560, 1.0 / 1820, 1.0 / 4368, 1.0 / 8008, 1.0 / 11440,
         1.0 / 12870, 1.0 / 11440, 1.0 / 8008, 1.0 / 4368, 1.0 / 1820, 1.0 / 560, 1.0 / 120,
         1.0 / 16, 1},
    };
    COUNT(9);
    COUNT_MADDS(n * (n + 1) / 2 + 4 * n); /* the sums and the scaling */
    double ap[MAXN + 1], aq[MAXN + 1];
    for (int k = n + 1; k <= 8; k++)
        ap[k] = aq[k] = 0; /* (binomial_sums reads 9, or 5) */
    double rel = 4.0 * (2 * n + 4) * UNIT_ROUNDOFF;
    double wk = 1, g = 0;
    for (int k = 0; k <= n; k++) {
        double f = wk * INV_BINOM[n][k];
        ap[k] = pt->pt[k] * f;
        aq[k] = pt->qt[k] * f;
        g += (pt->tol[k] + rel * (fabs(pt->pt[k]) + fabs(pt->qt[k]))) * wk;
        wk *= w;
    }
    /* sum_k C(j, k) / C(n, k) |.| w^k <= sum_k |.| w^k: one bound serves
     * every coefficient */
    double tol = 2 * g + DBL_MIN;
    double *b = aq;
    binomial_sums(aq, n);
    /* (branch-free: the signs are data; the sign bits count only where
     * every sign is certain, which is all that is read of them) */
    int certain = 1;
    uint64_t neg = 0;
    for (int j = 0; j <= n; j++) {
        uint64_t bits;
        memcpy(&bits, &b[j], sizeof bits);
        certain &= fabs(b[j]) > tol;
        neg |= bits;
    }
    if (certain && !(neg >> 63))
        return BERN_CLEAR;
    int vq = changes_certain(b, n);
    if (qb != NULL) {
        for (int j = 0; j <= n; j++)
            qb->b[j] = b[j];
        qb->err = tol;
        qb->even = certain && vq % 2 == 0;
    }
    /* (an odd count for p means p(x + w) < 0, so q(x + w) < 0 too: q's
     * count is odd, and qb->even already 0) */
    if (!(certain && vq == 1))
        return BERN_UNKNOWN;
    COUNT_MADDS(n * (n + 1) / 2);
    binomial_sums(ap, n);
    b = ap;
    *pend = b[n];
    for (int j = 0; j <= n; j++)
        certain &= fabs(b[j]) > tol;
    return certain && changes_certain(b, n) == 1 ? BERN_ONE : BERN_UNKNOWN;
}

/* A point of (a, b) to split at: the midpoint, geometric when the interval
 * spans more than a factor 8 (roots near 0), b / 16 from a = 0. */
static double isolation_split(double a, double b)
{
    if (a == 0)
        return b * 0.0625;
    if (b > 8 * a)
        return sqrt(a) * sqrt(b);
    return a + 0.5 * (b - a);
}

#define ISOLATED 1
#define CLEARED 0
#define UNRESOLVED (-1)
#define SCANNED 2 /* isolated by the derivative method (never_late looks again) */

static int derivative_method(const double c[], int n, double lo, double T,
                             double x0, double skin, double *t, int *graze);
static int scan_pieces(const double c[], double d[MAXN + 1][MAXN + 1], int n,
                       double lo, double T, const double crit[], int nc,
                       double skin, const TouchValues *tv, double *t, int *graze);
static double touch_critical(const double p[], double d[MAXN + 1][MAXN + 1],
                             int n, double lo, double hi, double x);

/* dp[0..n-1]: the coefficients of p' (p of degree n). */
static void derivative(const double p[], int n, double dp[])
{
    for (int i = 0; i < n; i++)
        dp[i] = (i + 1) * p[i + 1];
}

/* The one simple root of p in (a, b), p(a) = pa > 0 > pb = p(b): safeguarded
 * Newton from the regula falsi point. */
static double polish_isolated(const double p[], int n, double a, double b,
                              double pa, double pb)
{
    double dp[MAXN];
    derivative(p, n, dp);
    double x0 = a + (b - a) * (pa / (pa - pb));
    if (!(x0 > a && x0 < b))
        x0 = split_point(a, b);
    PHASE(2);
    return refine_root(p, dp, n, a, b, 1, 0, x0);
}

/* de Casteljau's n rounds written out for degree 8, on w0..w8 (the
 * coefficients), into left[] and right[] (halves, split_at): STEP(j, k)
 * sets w_j from w_j and w_k, j ascending within a round, as the loops do --
 * the same operations in the same order. */
#define CASTELJAU_8(STEP) \
    do { \
        left[0] = w0; \
        right[8] = w8; \
        STEP(0, 1); STEP(1, 2); STEP(2, 3); STEP(3, 4); STEP(4, 5); STEP(5, 6); STEP(6, 7); STEP(7, 8); \
        left[1] = w0; \
        right[7] = w7; \
        STEP(0, 1); STEP(1, 2); STEP(2, 3); STEP(3, 4); STEP(4, 5); STEP(5, 6); STEP(6, 7); \
        left[2] = w0; \
        right[6] = w6; \
        STEP(0, 1); STEP(1, 2); STEP(2, 3); STEP(3, 4); STEP(4, 5); STEP(5, 6); \
        left[3] = w0; \
        right[5] = w5; \
        STEP(0, 1); STEP(1, 2); STEP(2, 3); STEP(3, 4); STEP(4, 5); \
        left[4] = w0; \
        right[4] = w4; \
        STEP(0, 1); STEP(1, 2); STEP(2, 3); STEP(3, 4); \
        left[5] = w0; \
        right[3] = w3; \
        STEP(0, 1); STEP(1, 2); STEP(2, 3); \
        left[6] = w0; \
        right[2] = w2; \
        STEP(0, 1); STEP(1, 2); \
        left[7] = w0; \
        right[1] = w1; \
        STEP(0, 1); \
        left[8] = w0; \
        right[0] = w0; \
    } while (0)

/* The Bernstein coefficients of both halves of the interval (de Casteljau
 * at 1/2: n rounds of averages of neighbours, one triangle): left[k] is the
 * first entry after round k, right[n - k] the last.  (Each half used to be
 * a triangle of its own, the right one on the reversed coefficients: the
 * same averages with their terms swapped, so the same values, at twice the
 * cost.)  left and right may not be in.  Written out for degree 8 -- the
 * common degree, and the one whose last entries sit in fixed registers --
 * for the reason of binomial_sums. */
static void halves(const double in[], int n, double left[], double right[])
{
    if (n == 8) {
        double w0 = in[0], w1 = in[1], w2 = in[2], w3 = in[3], w4 = in[4], w5 = in[5],
               w6 = in[6], w7 = in[7], w8 = in[8];
#define AVG(j, k) w##j = (w##j + w##k) * 0.5
        CASTELJAU_8(AVG);
#undef AVG
        return;
    }
    double w[MAXN + 1];
    for (int j = 0; j <= n; j++)
        w[j] = in[j];
    left[0] = in[0];
    right[n] = in[n];
    for (int k = 1; k <= n; k++) {
        for (int j = 0; j <= n - k; j++)
            w[j] = (w[j] + w[j + 1]) * 0.5;
        left[k] = w[0];
        right[n - k] = w[n - k];
    }
}

/* The Bernstein coefficients of [0, t] and [t, 1] of the interval's (de
 * Casteljau at t in (0, 1): n rounds of w_j + t (w_{j+1} - w_j), each a
 * convex combination of its parents, rounded three times: within 4 u M of
 * exact, M the parent's largest magnitude).  left and right may not be in. */
static void split_at(const double in[], int n, double t, double left[], double right[])
{
    if (n == 8) {
        /* written out for degree 8, as halves and for its reason (the
         * loop's operations in its order: the same bits); the first split
         * of most windows near complex roots (bernstein_clear) */
        double w0 = in[0], w1 = in[1], w2 = in[2], w3 = in[3], w4 = in[4], w5 = in[5],
               w6 = in[6], w7 = in[7], w8 = in[8];
#define LERP(j, k) w##j = w##j + t * (w##k - w##j)
        CASTELJAU_8(LERP);
#undef LERP
        return;
    }
    double w[MAXN + 1];
    for (int j = 0; j <= n; j++)
        w[j] = in[j];
    left[0] = in[0];
    right[n] = in[n];
    for (int k = 1; k <= n; k++) {
        for (int j = 0; j <= n - k; j++)
            w[j] = w[j] + t * (w[j + 1] - w[j]);
        left[k] = w[0];
        right[n - k] = w[n - k];
    }
}

/* Is q > 0 on the interval of qb (its Bernstein coefficients, certain signs,
 * an even count)?  Bisection in the Bernstein basis: de Casteljau's
 * midpoint steps give both halves' coefficients by n(n + 1)/2 averages
 * (halves; no Taylor shift), a piece is cleared when its coefficients are
 * certainly positive, and the answer is no (0: not known) at the first piece
 * whose signs are uncertain or change an odd number of times (q crosses 0
 * there) or beyond CLEAR_DEPTH halvings.  Each average rounds once, by at most u
 * times the largest coefficient M of the parent (the children's are convex
 * combinations of its), and the parent's errors are averaged: a child's
 * bound is the parent's plus 2 n u M (twice, for safety) plus DBL_MIN (for
 * underflow).  Aimed at windows with no root but complex roots near the
 * axis, where Descartes' count stays 2 on every interval around them until
 * the intervals are about as narrow as the imaginary parts.
 * The first split is at t0 (relative to the interval) instead when it lies
 * DIP_INSIDE or more from either end: where the failed guess saw p dip towards such roots
 * (speculate_first_root's *dip).  Split at the dip, each side starts where
 * p is least and rises away from it, and is often cleared at once, where
 * halves would first have to shrink around it (measured: bench/roots_ab.py
 * noroot8_near 0.86 of the instructions and 0.87 of the time at the median
 * and in the mean; the other families within noise; the same answers).  A
 * split at t rounds three times per entry (split_at): 4 n u M, twice. */
#define CLEAR_DEPTH 12
/* What a split adds to the error bound of its pieces' coefficients, M the parent's largest
 * magnitude: 2 n u M for halves, 8 n u M for split_at (see bernstein_clear, whose bound
 * this is; bench/near_window.c prices its certificate with the same one). */
static inline double split_rounding(int at, int n, double M)
{
    return (at ? 8 : 2) * n * UNIT_ROUNDOFF * M;
}

/* A dip counts for a first split when it is at least this fraction of the
 * interval from either end (bernstein_clear, isolate_first_root). */
#define DIP_INSIDE 0.0625
static FORCE_INLINE int bernstein_clear_core(const BernQ *qb, int n, double t0)
{
    double st[CLEAR_DEPTH + 2][MAXN + 1], err[CLEAR_DEPTH + 2];
    int depth[CLEAR_DEPTH + 2];
    int top = 0;
    for (int j = 0; j <= n; j++)
        st[0][j] = qb->b[j];
    err[0] = qb->err;
    depth[0] = 0;
    top = 1;
    while (top > 0) {
        top--;
        double *b = st[top], e = err[top];
        int d = depth[top];
        /* with every sign certain (no zeros), the number of sign changes
         * is odd exactly when the end signs differ */
        double lo = b[0], hi = b[0], amin = fabs(b[0]);
#define SCAN(j)                                            \
    lo = b[j] < lo ? b[j] : lo;                            \
    hi = b[j] > hi ? b[j] : hi;                            \
    amin = fabs(b[j]) < amin ? fabs(b[j]) : amin
        if (n == 8) {
            /* written out for degree 8, in the loop's order (the same
             * values, NaN ignored alike): with the degree a constant
             * (bernstein_clear_8) the loop's control cost more than its
             * work, on the 25 pieces a window near complex roots takes */
            SCAN(1); SCAN(2); SCAN(3); SCAN(4); SCAN(5); SCAN(6); SCAN(7); SCAN(8);
        } else {
            for (int j = 1; j <= n; j++) {
                SCAN(j);
            }
        }
#undef SCAN
        if (!(amin > e) || (b[0] > 0) != (b[n] > 0))
            return 0;
        if (lo > 0)
            continue;
        double M = -lo > hi ? -lo : hi;
        if (d == CLEAR_DEPTH)
            return 0;
        /* halves: the right one over b's slot, the left one above it (so
         * it is looked at first) */
        COUNT_MADDS(n * (n + 1) / 2);
        double whole[MAXN + 1];
        whole[0] = b[0]; /* (gcc -Wmaybe-uninitialized cannot see n >= 1) */
        for (int j = 1; j <= n; j++)
            whole[j] = b[j];
        int at = d == 0 && t0 > DIP_INSIDE && t0 < 1 - DIP_INSIDE;
        if (at)
            split_at(whole, n, t0, st[top + 1], b);
        else
            halves(whole, n, st[top + 1], b);
        double ec = e + split_rounding(at, n, M) + DBL_MIN;
        err[top] = err[top + 1] = ec;
        depth[top] = depth[top + 1] = d + 1;
        top += 2;
    }
    return 1;
}

/* bernstein_clear_core with n = 8 a constant (its loops' bounds fixed), and
 * for any n: each out of line (a rare path in the copies).  Measured with
 * the scan and split_at written out for degree 8 (bench/roots_ab.py
 * --sweeps 21, aligned, three runs against the code before: complex roots
 * near the window 0.74 of the time at the median and 0.80 in the mean, no
 * root in the window 0.91 and tmax = inf 0.87 in the mean, the rest within
 * noise; 0.88 of the instructions near the window; the same answers);
 * without this copy (bernstein_clear out of line for any n, as before), the
 * same written-out code took 1.30 times as long near the window as with it
 * (so about 0.96 of the loops before), for 0.99 of its instructions. */
NOINLINE static int bernstein_clear_8(const BernQ *qb, double t0)
{
    return bernstein_clear_core(qb, 8, t0);
}

NOINLINE static int bernstein_clear_any(const BernQ *qb, int n, double t0)
{
    return bernstein_clear_core(qb, n, t0);
}

static int bernstein_clear(const BernQ *qb, int n, double t0)
{
    if (n == 8)
        return bernstein_clear_8(qb, t0);
    return bernstein_clear_any(qb, n, t0);
}

/* A guess at the first root: Laguerre's method from 0, each step taken
 * towards the right (the one of its two square-root signs that moves x
 * up): for a polynomial whose roots are all real it converges monotonically
 * to the first root after its start, cubically near it, from any start --
 * and from 0, the first positive root is the one we want.  Returns 1 with
 * *r set once the steps end (GUESS_DONE, below); gives up (0) where the square
 * root's argument is negative (complex roots in the way) and Newton may not
 * step instead (below), when no step to the right exists, when x leaves
 * (0, T), when a step from the fifth on has neither halved nor shrunk by
 * more than the step before (far from every root Laguerre creeps, then
 * speeds up: it gives up only while it is not slowing down), or after
 * SPECULATE_STEPS.  Nothing is certain about the guess: it is trusted only once a Bernstein test on
 * (0, r (1 + 2^-20)] finds exactly one root of p and of q there (then r is
 * the first root, polished as any isolated root).  Measured on the
 * benchmark families (tried, then, where p's control polygon on the window
 * crossed 0): certified guesses on 146 of 250 generic octics, 157 of 250 at
 * degree 16 and 128 of 250 quartics, against 104, 89 and 107 for Newton
 * from where the control polygon crosses 0 (Newton from far away creeps:
 * a step is about x / n while p ~ x^n, and the window is 17 times the first
 * root at the median).
 *
 * A touch ahead (a double root, or two real roots or a complex pair within
 * the rounding noise of one) has a signature: Laguerre converges to a root of
 * multiplicity 2 only linearly, each step 1 - n / (2 + sqrt((n - 1)(2n - 4)))
 * times the one before (0.25 at degree 3, 0.284 at 8, 0.289 at 16; a triple
 * root gives about 0.4, a simple one a ratio falling to 0).  After
 * TOUCH_STEADY ratios in a row in [TOUCH_RATIO_LO, TOUCH_RATIO_HI] (up to
 * TOUCH_EXTRA steps beyond SPECULATE_STEPS while they last) the guess turns
 * to Newton on p' -- the critical point is a simple root of p', so that
 * converges quadratically (2-3 steps) where Laguerre would crawl -- and,
 * when p there is within 2^20 times the rounding bound (a complex pair
 * clear of the axis is not: not worth the derivative method), *touch gets
 * it.  Like the guess, it only chooses where to look (isolate_first_root).
 * Measured on bench/roots.py's families (250 polynomials each): 3 ratios in
 * [0.25, 0.31] cost 1 of 145 certified guesses on generic octics and none of
 * 153 at degree 16 (2 ratios in [0.2, 0.45] cost 10 and 16, and sent 180 of
 * 250 no-root windows with complex pairs near the axis towards a touch; now
 * 4); a touch is found on 175 of the 250 grazes (the others: complex roots
 * in the way, where the square root's argument goes negative at once, or
 * Laguerre still creeping).
 *
 * Where it gives up on complex roots in the way (the square root's argument
 * negative, p'' > 0) or Newton on p' ends at a dip too high for a touch,
 * *dip gets a point near where p is least (one Newton step on p' from x, or
 * that dip): bernstein_clear splits there first (else *dip stays 0).
 *
 * Complex roots near the first real root can also turn a step past it: p
 * is negative at the new x (after which the steps to the right would head
 * for the next root, creep and give up).  Returns OVERSHOT then, with *over
 * = x and *r a start inside the step for Newton (from x, else the middle):
 * a root lies in (0, x), and the Bernstein test on (0, x (1 + 2^-20)]
 * certifies it as for a converged guess.  An iterate one rounding past a
 * root it has converged to is caught the same way, where the next step
 * used to bring it back.  Measured on bench/roots.py's families: 52 of 250
 * generic octics overshoot (50 certified), 50 quartics (50), 51 at degree
 * 16 (49); bench/roots_ab.py --sweeps 15, aligned: generic octics 0.94 of
 * the time at the median and 0.90 in the mean, quartics 0.96 / 0.88,
 * degree 12 0.92 / 0.90, degree 16 0.98 / 0.89, the rest within noise;
 * 0.89-0.91 of the instructions; the same answers, bit for bit.
 *
 * With a bracket caught, the guess can also step where Laguerre's square
 * root's argument is negative: a Newton step to the right (p falling) takes
 * Laguerre's place, up to GUESS_NEWTON times a guess -- past the complex
 * pair's pull Laguerre's steps often resume, and a step past the root is an
 * overshoot like any other (measured: bench/roots_ab.py --instructions,
 * generic octics 0.921, degree 16 0.941, grazes 0.962, quartics 0.982,
 * the rest 1.00-1.02; 1 and 4 steps: generic octics 0.943 and 0.921;
 * timed --sweeps 21, aligned, median / mean: generic octics 1.00 / 0.93,
 * degree 12 0.99 / 0.94, degree 16 0.99 / 0.96, grazes 0.98 / 0.98,
 * quartics 1.00 / 0.98 -- the solves it moves are the costly ones -- but
 * complex roots near the window 1.03 / 1.03, where the steps lead nowhere;
 * the same answers, bit for bit). */
#define OVERSHOT 2
#define GUESS_NEWTON 2
#define SPECULATE_STEPS 8
#define TOUCH_EXTRA 4
#define TOUCH_STEPS 6
#define TOUCH_RATIO_LO 0.25
#define TOUCH_RATIO_HI 0.31
#define TOUCH_STEADY 3
#define TOUCH_NEAR 0x1p20
/* The guess's last step: Laguerre stops after a step below PRECISE_FROM
 * (relative), or below GUESS_DONE when it was at most GUESS_FAST of the
 * step before (cubic convergence under way: the next step would be below
 * about 2^-14 (2^-4)^3 = 2^-26, and the compensated Newton of the polish,
 * one or two steps, finishes it where a further Laguerre step -- three
 * Horner chains, a square root, a division -- only confirmed it).  The
 * ratio keeps the linear approach to a double root going until
 * TOUCH_STEADY sees it (without it: a touch next to a complex pair,
 * tests/runtime/test_touch_critical.py, lost the touch's path for a dozen
 * Taylor points).  Measured against PRECISE_FROM alone, with the
 * compensated steps on the fma instruction (FMA_DISPATCH):
 * bench/roots_ab.py --instructions generic octics 0.990, degree 12 0.985,
 * degree 16 0.960, the rest within 1 %; --sweeps 21 aligned generic octics
 * 0.97 at the median and in the mean, degree 16 0.98 / 0.95, the rest
 * 0.95-1.00; 0 of 2250 answers moved.  (Without the ratio test, 2^-14:
 * 0.982 of generic octics' instructions; before those fma steps 2^-17
 * cost the collision family 2-4 %: a compensated step cost more than a
 * Laguerre step then.) */
#define GUESS_DONE 0x1p-14
#define GUESS_FAST 0x1p-4
static int speculate_first_root(const double p[], int n, double T, double *r,
                                double *touch, double *dip, double *over)
{
    PHASE(2);
    double x = 0, last = 0, qprev = 0, xprev = 0;
    int newton = 0; /* Newton steps in Laguerre's place (below) */
    int critical = 0, steady = 0; /* Newton on p' (after the double-root signature) */
    *touch = 0;
    for (int it = 0; it < SPECULATE_STEPS + TOUCH_EXTRA + TOUCH_STEPS; it++) {
        if (!critical && it >= SPECULATE_STEPS && (steady == 0 || it >= SPECULATE_STEPS + TOUCH_EXTRA))
            return 0;
        COUNT_MADDS(3 * n);
        /* p, p', p''/2 at x; at 0 (the first step, only there) the
         * coefficients, the values the chains give (a zero's sign aside,
         * which no test below sees; tests/runtime/test_c_kernels.py): one Horner
         * evaluation's latency less on every guess (measured: bench/roots_ab.py
         * --sweeps 21, 0.97 of the time of generic octics at the median and
         * 0.98 in the mean, collision polynomials 0.97 / 0.96, no root with
         * tmax = inf 0.93 / 0.97; 0.99 of the instructions) */
        double f = p[0], d1 = p[1], d2 = p[2];
        if (it > 0) {
            f = p[n], d1 = 0, d2 = 0;
            for (int i = n - 1; i >= 0; i--) {
                d2 = d2 * x + d1;
                d1 = d1 * x + f;
                f = f * x + p[i];
            }
        }
        if (critical) {
            /* Newton on p' towards the critical point: a simple root of
             * p' where p'' > 0 (a minimum of p > 0) */
            if (!(d2 > 0))
                return 0;
            double s = d1 / (2 * d2);
            x -= s;
            if (!(x > 0 && x < T))
                return 0;
            if (fabs(s) <= PRECISE_FROM * x) {
                if (fabs(f) <= TOUCH_NEAR * noise_factor(n) * horner_abs(p, n, x, 0))
                    *touch = x;
                else
                    *dip = x; /* a dip clear of the axis: complex roots */
                return 0;
            }
            if (critical > 1 && !(fabs(s) <= 0.5 * fabs(last)))
                return 0;
            critical++;
            last = s;
            continue;
        }
        if (f == 0) {
            *r = x;
            return x > 0;
        }
        if (f < 0) {
            /* Past a root (see above): one in (xprev, x); *r where Newton
             * from x points, inside that, else its middle */
            double y = x - f / d1;
            *r = y > xprev && y < x ? y : xprev + 0.5 * (x - xprev);
            *over = x;
            return OVERSHOT;
        }
        /* u = (n - 1) f^2 times Laguerre's discriminant (n - 1)(n h - g^2),
         * g = p'/p, h = g^2 - p''/p: its sign, and the step
         * n / (g - sqrt(disc)) = n f / (p' - sign(f) sqrt((n - 1) u)), from
         * one division where g, h and the step took three, two of them one
         * after the other (measured: bench/roots_ab.py --sweeps 11, generic
         * octics 0.95 of the time at the median, quartics 0.96, collision
         * polynomials 0.95, grazes 0.98; rounding moves 10 of 1500 answers,
         * all touches or double roots split by rounding).  Overflow of the
         * products (windows beyond 2^64 at degree 8) makes u NaN: no guess. */
        double u = (n - 1) * (d1 * d1) - 2 * n * (f * d2);
        double s;
        if (!(u >= 0)) {
            /* complex roots in the way: one Newton step on p' towards the
             * dip, and in Laguerre's place, up to GUESS_NEWTON times while
             * p falls, a Newton step (see above) */
            if (d2 > 0)
                *dip = x - d1 / (2 * d2);
            if (newton == GUESS_NEWTON || !(d1 < 0))
                return 0;
            newton++;
            s = f / d1;
        } else {
            s = n * f / (d1 - copysign(sqrt((n - 1) * u), f));
        }
        if (!(s < 0))
            return 0;
        xprev = x;
        x -= s;
        if (!(x > 0 && x < T))
            return 0;
        double q = it > 0 ? s / last : 0;
        if (fabs(s) <= PRECISE_FROM * x ||
            (fabs(s) <= GUESS_DONE * x && q <= GUESS_FAST)) {
            *r = x;
            return 1;
        }
        steady = q >= TOUCH_RATIO_LO && q <= TOUCH_RATIO_HI ? steady + 1 : 0;
        if (steady >= TOUCH_STEADY) {
            critical = 1; /* linear convergence: a double root ahead */
            last = s;
            continue;
        }
        if (it >= 4 && !(fabs(s) <= 0.5 * fabs(last)) && !(q < qprev))
            return 0;
        qprev = q;
        last = s;
    }
    return 0;
}

/* First event in (0, T] for p (T <= FAST_LIMIT, p(0) > 0) by Budan-Fourier
 * bisection.  Returns ISOLATED with *t (and *graze) set (SCANNED where the
 * derivative method found it), CLEARED when there is nothing in (0, T], or
 * UNRESOLVED with *a the left end of what is left to the derivative
 * method. */
static int isolate_first_root(const double p[], int n, double skin,
                              double T, double failed_w, double *t, int *graze,
                              double *a_out)
{
    PHASE(1);
    double e = skin >= 0 ? noise_factor(n) : 0;
    double sk = skin > 0 ? skin : 0;
    Point a, stack[MAX_SPLITS + 1]; /* a: left end; stack: right ends */
    int top = 0, splits = 0;
    *a_out = 0;
    point_at_zero(p, n, e, sk, &a);
    if (!(a.qt[0] - a.tol[0] > 0))
        return UNRESOLVED; /* within the skin at 0: no envelope to count */
    /* Descartes, or q(0) beats every negative term (unless that very test
     * has failed already: cleared_at_once) */
    if (a.vq == 0 || (T != failed_w && clearly_positive(&a, n, T, 1)))
        return CLEARED;
    /* A guess first, then a certificate: the guess (Laguerre from 0) and
     * one Bernstein test on (0, r (1 + 2^-20)] settle most solves with a
     * root, which the test on the whole window before them (when it did
     * not settle the solve itself) only delayed; and that test no longer
     * forms p's coefficients for the control polygon, whose crossing was
     * the guess's gate.  Measured against both (bench/roots_ab.py
     * --instructions, and timed --sweeps 11, median / mean): generic
     * octics 0.90 of the instructions, 0.87 / 0.91 of the time; quartics
     * 0.88, 0.90 / 0.92; degree 16 0.85, 0.79 / 0.89; no root in the
     * window 0.98, 0.97 / 0.96; tmax = inf 0.95, 1.03 / 0.93; collision
     * polynomials 0.92, 1.33 / 1.00 -- that median lies between the
     * family's two modes (solves settled at 0, and the rest at 0.8-1.0),
     * where the windows the whole-window test would have settled at once
     * pay the failed guess. */
    double pT, r, touch;
    double dip = 0;
    double over = 0;
    int guess = speculate_first_root(p, n, T, &r, &touch, &dip, &over);
    if (guess) {
        /* (overshot: the Bernstein test up to the step's end, where p was
         * negative, and Newton from *r with plain evaluation first) */
        double w = guess == OVERSHOT ? over + over * 0x1p-20 : r + r * 0x1p-20;
        w = w < T ? w : T;
        /* The polish's first step (compensated, from r) ahead of the
         * certificate, which does not need it: its chain's latency then
         * passes while the Bernstein sums run (measured: bench/roots_ab.py
         * --sweeps 21 and 31, aligned, generic octics 0.97-0.98 of the time
         * at the median, 0.98-0.99 in the mean, quartics 0.96-1.00,
         * collision polynomials 0.89-1.00 / 0.93-0.98; the same
         * instructions within 0.6 %; where the certificate fails, one
         * evaluation wasted).  Counted where the polish uses it. */
        double dp[MAXN], first[2];
        derivative(p, n, dp);
        int ahead = guess != OVERSHOT && scale_exponent(r, n) == 0;
        if (ahead)
            first[0] = compensated_slope_ahead(p, dp, n, r, &first[1]);
        PHASE(1);
        if (bernstein_test(&a, n, w, &pT, NULL) == BERN_ONE) {
            PHASE(2);
            *t = refine_root_from(p, dp, n, 0, w, 1, guess == OVERSHOT ? 0 : PRECISE_NOW, r,
                                  ahead ? first : NULL);
            *graze = 0;
            return ISOLATED;
        }
    }
    PHASE(1);
    double from = 0; /* > 0: (0, from] is settled, the counts go on from it */
    /* A touch ahead (speculate_first_root): (0, lo] is certified clear
     * by the Bernstein test (q's coefficients all positive), then the
     * derivative method settles (lo, hi] -- small, so with few roots of
     * the derivatives in it -- and the counts go on from hi if it finds
     * nothing there.  Replaces, on the grazes, the Taylor points that
     * bisect down to the touch (6.3 a graze) and the derivative method
     * on the wide interval they leave (measured: bench/roots_ab.py
     * graze8 median 0.56, mean 0.63 of the time without it; other
     * families within noise).  hi is 3 widths to the right (from the
     * middle of a symmetric interval -- the critical point to within
     * rounding -- the fma noise of p' there once sent the derivative
     * method's safeguarded Newton into bisection: refine_root now stops
     * such a step).  The derivative method's Newton for the critical
     * point starts at the touch itself, which the guess found by the same
     * Newton: it stops at once (measured: 5.0 Newton steps on p' a graze
     * before, 2.4 after, counted in the pure-Python port; with touch_point
     * and refine_root's stop, roots_ab --sweeps 15 graze8 0.92 of the time
     * at the median, 0.97 in the mean, instructions 0.96).  Before the
     * test on the whole window, which a touch ahead leaves undecided: q
     * dips to 0 there, so q's coefficients on (0, T] are neither all
     * positive nor one change with p's (on bench/roots.py's families:
     * undecided on all 179 solves with a touch ahead).  (lo, hi] is
     * settled by scan_pieces on the critical point that touch_critical
     * certifies in one pass, as the derivative method would settle it
     * (measured: bench/roots_ab.py --sweeps 21, aligned, graze8 0.92 of the
     * time at the median, 0.96 in the mean; the other families within
     * noise; 5 of 3250 answers moved -- touches by a few ulps, where the
     * derivative method's convexity test had failed and its full recursion
     * found the critical point -- all right by the exact oracle); where the
     * pass cannot tell (1 of the 184 touches of the grazes), the derivative
     * method. */
    if (touch > 0 && skin >= 0) { /* (not for the no-graze baseline) */
        double lo = touch - touch * TOUCH_WIDTH, hi = touch + 3 * touch * TOUCH_WIDTH;
        hi = hi < T ? hi : T;
        if (bernstein_test(&a, n, lo, &pT, NULL) == BERN_CLEAR) {
            int hit;
            PHASE(3);
            double d[MAXN + 1][MAXN + 1];
            derivative(p, n, d[n - 1]);
            derivative(d[n - 1], n - 1, d[n - 2]);
            double b = touch_critical(p, d, n, lo, hi, touch);
            if (b > 0) {
                /* (b < hi: no scaling at b when none at hi, touch_critical's) */
                TouchValues tv;
                touch_values(p, d[n - 1], d[n - 2], n, b, hi, &tv);
                hit = scan_pieces(p, d, n, lo, hi, &b, 1, skin, &tv, t, graze);
            } else {
                hit = derivative_method(p, n, lo, hi, touch, skin, t, graze);
            }
            PHASE(1);
            /* (on (lo, hi], convex by touch_critical's certificate, p falls
             * to b alone: no crossing pair can hide there, not SCANNED) */
            if (hit)
                return b > 0 ? ISOLATED : SCANNED;
            if (hi == T)
                return CLEARED;
            from = hi;
        }
    }
    if (from == 0) {
        /* the whole window, unless a touch's interval settled (0, from] */
        BernQ qb;
        int bern = bernstein_test(&a, n, T, &pT, &qb);
        if (bern == BERN_CLEAR)
            return CLEARED;
        if (bern == BERN_ONE) {
            *t = polish_isolated(p, n, 0, T, a.px, pT);
            *graze = 0;
            return ISOLATED;
        }
        if (qb.even && bernstein_clear(&qb, n, dip / T)) /* (after a guess that failed) */
            return CLEARED;
    }
    Taylor tb;
    taylor_table(p, n, e, sk, &tb);
    /* the counts start from `from` when a touch's interval was settled: its
     * Point, with q's sign there certain */
    if (!point_at(&tb, n, T, &stack[top++]) ||
        (from > 0 && !(point_at(&tb, n, from, &a) && a.qt[0] - a.tol[0] > 0))) {
        *a_out = from; /* (0 unless so) */
        return UNRESOLVED;
    }
    int tested = from == 0; /* (0, T] has had its Bernstein test */
    int early_tried = 0;
    for (;;) {
        const Point *b = &stack[top - 1];
        double w = b->x - a.x;
        /* (an odd count for p means a sign change: no bound can clear it) */
        int odd = (a.vp - b->vp) % 2 != 0;
        if (a.vq == b->vq || (!odd && (clearly_positive(&a, n, w, 1) ||
                                       clearly_positive(b, n, w, -1)))) {
            /* nothing in (a, b]: on to the next interval */
            a = *b;
            tested = 0;
            if (--top == 0)
                return CLEARED;
            continue;
        }
        if (a.vp - b->vp == 1 && a.vq - b->vq == 1) {
            *t = polish_isolated(p, n, a.x, b->x, a.px, b->px);
            *graze = 0;
            return ISOLATED;
        }
        /* Descartes in the Bernstein basis, where the counts fail: only for
         * an odd count, where a root is certain and the test may find it
         * alone (measured: testing even counts too -- grazes, complex pairs
         * -- cost more than it saved); (0, T] had it before the loop */
        if (odd && !tested && bernstein_test(&a, n, w, &pT, NULL) == BERN_ONE) {
            *t = polish_isolated(p, n, a.x, b->x, a.px, b->px);
            *graze = 0;
            return ISOLATED;
        }
        tested = 0;
        /* Two roots in (a, b] by both counts, and (a, b] within a quarter
         * of b: mostly a double root (a touch) or a close pair, which the
         * splits below approach by one halving per two Taylor points
         * (measured: 17 points per graze); the derivative method settles
         * it at once.  Once per solve: where it finds nothing there (a
         * complex pair near the axis), the splits go on. */
        int early = !early_tried && a.vp - b->vp == 2 && a.vq - b->vq == 2 &&
                    w <= EARLY_WIDTH * b->x;
        early_tried |= early;
        if (!early) {
            /* Split at twice the distance to where p's tangent at a meets 0
             * when that is inside: the first root is usually near it, so
             * the left part holds it alone more often than a half does
             * (measured: 6-15 % fewer multiply-adds per solve on every
             * benchmark family; 1.5 and 3 were worse on some).  A tangent
             * that meets 0 within MIN_WIDTH of a puts a root or a touch
             * there: split just beyond it, so that the next interval is
             * that small (a half would take a dozen points to get there).
             * The first split of all goes where the failed guess saw p dip
             * (*dip of speculate_first_root), when it is well inside: as
             * for bernstein_clear, each side then starts at p's least
             * (measured: bench/roots_ab.py noroot8_near 0.93 of the
             * instructions, 0.94 of the time in the mean; one touch of 2250
             * answers moved, 8e-9 from its critical point instead of 2e-8). */
            double m = isolation_split(a.x, b->x);
            double mt = a.x + SPLIT_NEWTON * (-a.px / a.dpx);
            double hair = a.x + 4 * MIN_WIDTH * b->x;
            if (splits == 0 && dip > a.x + DIP_INSIDE * w && dip < b->x - DIP_INSIDE * w)
                m = dip;
            else if (a.dpx < 0 && mt > a.x && mt < b->x && mt - a.x > MIN_WIDTH * b->x)
                m = mt;
            else if (a.dpx < 0 && mt > a.x && mt - a.x <= MIN_WIDTH * b->x &&
                     hair < b->x)
                m = hair;
            if (splits < MAX_SPLITS && w > MIN_WIDTH * b->x && m > a.x &&
                m < b->x && point_at(&tb, n, m, &stack[top])) {
                splits++;
                top++;
                continue;
            }
        }
        /* The counts do not resolve (a, b] (a double root, a tight cluster)
         * or cannot be trusted at m, or the early try above: the derivative
         * method, on (a, b] only (small: few critical points). */
        int hit = derivative_method(p, n, a.x, b->x, 0, skin, t, graze);
        PHASE(1);
        if (hit)
            return SCANNED;
        if (!(b->qt[0] - b->tol[0] > 0)) {
            /* p has no root in (a, b], so p(b) > 0, but q(b) is not: the
             * counts for q cannot go on from b */
            *a_out = b->x;
            return UNRESOLVED;
        }
        a = *b;
        if (--top == 0)
            return CLEARED;
    }
}

/* ------------------------------------------------------------------ */
/* Derivative method (Yuksel)                                           */
/* ------------------------------------------------------------------ */

/* The derivatives d[m] of degrees m = n .. CHAIN_FIRST(n) (the derivative
 * of order n - m): those the derivative method always reads (convex_on
 * reads p'''); critical_points forms the rest, down to degree 2, only where
 * it needs them (the shortcut of convex_on does not: most calls on the
 * grazes). */
#define CHAIN_FIRST(n) ((n) - 3 > 1 ? (n) - 3 : 1)
static void derivative_chain(const double c[], int n,
                             double d[MAXN + 1][MAXN + 1])
{
    for (int i = 0; i <= n; i++)
        d[n][i] = c[i];
    for (int m = n; m > CHAIN_FIRST(n); m--)
        derivative(d[m], m, d[m - 1]);
}

/* Roots in (lo, T) of the polynomial P of degree m whose derivative's roots
 * in (lo, T) are crit[0..ncrit-1] (ascending): P is monotone between them.
 * Writes them ascending to out, to relative accuracy tol, and returns their
 * count.  Newton starts at x0 in a piece that holds it (0: none; a root
 * already known to about that accuracy), else at the piece's split point. */
static int roots_in_pieces(const double P[], const double D[], int m,
                           double lo, const double crit[], int ncrit,
                           double T, double tol, double x0, double out[])
{
    int count = 0;
    double a = lo;
    int sa = sign_at(P, m, lo, 0);
    for (int j = 0; j <= ncrit; j++) {
        double b = j < ncrit ? crit[j] : T;
        int sb = sign_at(P, m, b, 0);
        if (sb == 0) {
            if (j < ncrit)
                out[count++] = b;
        } else if (sa != 0 && sa != sb) {
            out[count++] = refine_root(P, D, m, a, b, sa, tol,
                                       x0 > a && x0 < b ? x0 : split_point(a, b));
        }
        a = b;
        sa = sb;
    }
    return count;
}

/* Is p'' certainly positive on [lo, T], beyond the rounding of its plain
 * Horner value anywhere there?  For 0 <= lo <= x <= T (no scaled
 * evaluation) and any m in [lo, T]: p''(x) >= p''(m) - h max |p'''|, with
 * h = max(m - lo, T - m) and |p'''(x)| <= sum |p'''_i| T^i (the computed
 * coefficients of p''' are within an ulp of the exact derivative's); each
 * plain value of p'' is within gamma_{2n} sum |p''_i| T^i (half of
 * noise_factor) of the exact one: twice that margin, and the bounds' own
 * roundings (rel).  Then every sign that the derivative method's level for
 * the roots of p'' evaluates is +: that level is empty whatever the levels
 * below it find, and the roots of p' come from an empty level -- the same
 * steps and bits as the full recursion, without the levels below (measured
 * on bench/roots.py's families: 167 of the 251 calls on the grazes, on the
 * small interval around a touch, and none elsewhere; roots_ab --sweeps 31
 * graze8 0.93-0.94 of the time at the median, 0.96-0.97 in the mean, the
 * same answers). */
static int convex_on(double d[MAXN + 1][MAXN + 1], int n, double lo, double T)
{
    if (n < 4 || !(lo >= 0) || scale_exponent(T, n) != 0)
        return 0;
    double m = lo + 0.5 * (T - lo), h = m - lo > T - m ? m - lo : T - m;
    double v = horner(d[n - 2], n - 2, m, 0, 0);
    double slope = horner_abs(d[n - 3], n - 3, T, 0);
    double size = horner_abs(d[n - 2], n - 2, T, 0);
    double rel = 4.0 * (n + 1) * UNIT_ROUNDOFF;
    return v - h * slope * (1 + rel) > 2 * noise_factor(n) * size * (1 + rel);
}

/* Roots in (lo, T) of the first derivative of d[n], found level by level
 * from the quadratic derivative upwards (the last level alone where
 * convex_on, then Newton from x0 where it is inside: roots_in_pieces). */
static int critical_points(double d[MAXN + 1][MAXN + 1], int n, double lo,
                           double T, double x0, double crit[])
{
    double r[2], disc, level[MAXN];
    int nl = 0;
    if (n < 3)
        return 0; /* (never: degree >= 3 here; says so to gcc -O3, which
                   * otherwise warns that d[2] may be unset) */
    if (convex_on(d, n, lo, T)) /* the roots of p' alone (above) */
        return roots_in_pieces(d[n - 1], d[n - 2], n - 1, lo, NULL, 0, T, TOL_CRITICAL, x0, crit);
    for (int m = CHAIN_FIRST(n); m > 2; m--) /* the rest of the chain */
        derivative(d[m], m, d[m - 1]);
    if (quad_roots(d[2][2], d[2][1], d[2][0], r, &disc) == 2)
        for (int i = 0; i < 2; i++)
            if (r[i] > lo && r[i] < T && (nl == 0 || r[i] > level[nl - 1]))
                level[nl++] = r[i];
    for (int m = 3; m < n; m++) {
        double next[MAXN];
        double tol = m == n - 1 ? TOL_CRITICAL : TOL_LEVEL;
        nl = roots_in_pieces(d[m], d[m - 1], m, lo, level, nl, T, tol, 0, next);
        for (int i = 0; i < nl; i++)
            level[i] = next[i];
    }
    for (int i = 0; i < nl; i++)
        crit[i] = level[i];
    return nl;
}

/* The root of p in (a, b], where p is monotone from p(a) (sign sa) to
 * p(b) = pb (precise, the other sign) and b is a critical point.  Near a
 * touch p(b) is tiny, and Newton from the middle crawls to the crossing by
 * halving its distance (measured: 27 compensated steps per such call on the
 * grazes); it starts instead where p(b) + p''(b) (x - b)^2 / 2 meets 0,
 * which for a touch is within rounding of the root (2 steps). */
static double crossing_before_critical(const double c[],
                                       double d[MAXN + 1][MAXN + 1], int n,
                                       double a, double b, int sa, double pb)
{
    double x0 = split_point(a, b);
    double h2 = -2 * pb / horner(d[n - 2], n - 2, b, 0, 0);
    double xq = b - sqrt(h2 > 0 ? h2 : 0);
    if (xq > a && xq < b)
        x0 = xq;
    return refine_root(c, d[n - 1], n, a, b, sa, 0, x0);
}

/* Where a touch is reported: the critical point b, which plain Newton on p'
 * leaves anywhere within p''s rounding noise (the derivative method stops it
 * there at once: refine_root), moved by one Newton step on p' evaluated
 * precisely (compensated) -- kept only when that step is within the noise
 * too, as a last step should be (where b needs no scaling).  Measured on
 * bench/roots.py's grazes against the exact critical points: the touches'
 * worst relative error 3.6e-15 before this step; an exact double root at 2
 * came out at 2 + ulp before it, at 2 after. */
static double touch_point(double d[MAXN + 1][MAXN + 1], int n, double b,
                          const TouchValues *tv)
{
    if (scale_exponent(b, n - 1) != 0)
        return b;
    COUNT(5);
    double slope, size, v;
    if (tv != NULL) { /* (touch_values: the same values) */
        COUNT_MADDS(3 * (n - 1) - 1 + 10 * (n - 1));
        v = tv->dv;
        slope = tv->ddv;
    } else {
        v = value_and_slope(d[n - 1], d[n - 2], n - 1, b, 0, 1, &slope, &size);
    }
    double x = b - v / slope;
    return fabs(x - b) <= NOISE_STEP * fabs(b) ? x : b;
}

/* Does p certainly rise on (a, b), so that its critical point b is a maximum
 * of p > 0?  By the sign of p' at the middle, where it is beyond the
 * rounding of its plain value (the derivative's coefficients are within an
 * ulp of the exact ones: inside that margin, as convex_on has it).  A
 * maximum is the farthest pass of the piece, never a touch, however near 0
 * it lies: within a skin, p(a) was nearer still (tests/runtime/
 * test_skin_oracle.py, an mpmath oracle: 28 of its 400 polynomials scaled
 * to the skin reported the maximum).  Where p' is within its noise (a piece too short
 * to tell), not certain: the graze check goes on as before. */
static int rises_to(const double d1[], int n, double a, double b)
{
    double m = a + 0.5 * (b - a);
    int k = scale_exponent(m, n - 1);
    double v = horner(d1, n - 1, m, k, 0);
    return v > 0 && !noise_holds(d1, n - 1, m, k, v, 0);
}

/* First root in (lo, T] of c (degree n >= 3, normalised, c(lo) > 0), given
 * its critical points there, crit[0..nc-1] (ascending), and d[n - 1], d[n - 2]
 * (p', p''): they split (lo, T] into monotone pieces, scanned left to right
 * with the graze check at each critical point.  tv: on a touch's interval
 * (nc = 1, T = hi), the values the scan reads, computed in one pass
 * (touch_values); else NULL. */
static int scan_pieces(const double c[], double d[MAXN + 1][MAXN + 1], int n,
                       double lo, double T, const double crit[], int nc,
                       double skin, const TouchValues *tv, double *t, int *graze)
{
    double a = lo;
    int sa = 1;
    /* p(b) by fma Horner (sign_at's value, kept for the graze check), and
     * whether the last graze check has already taken it at this b */
    double vb = 0;
    int kb = 0, vb_known = 0;
    for (int j = 0; j <= nc; j++) {
        double b = j < nc ? crit[j] : T;
        /* (with tv: the critical point, then the end; no scaling at either) */
        const TouchValues *at = tv != NULL && j == 0 ? tv : NULL;
        if (!vb_known) {
            kb = scale_exponent(b, n);
            if (at != NULL) {
                COUNT_MADDS(n);
                vb = at->vb;
            } else {
                vb = horner(c, n, b, kb, 1);
            }
        }
        vb_known = 0;
        int sb = (vb > 0) - (vb < 0);
        if (sb == 0) { /* exact zero: at a critical point it is a double root */
            *t = b;
            *graze = j < nc;
            return 1;
        }
        /* At a critical point p may be within the rounding noise (a touch),
         * and the sign of its fma Horner value is noise: a crossing there
         * is decided by the precise value (where b needs no scaling).  So at
         * the window's end when p is within its noise there: a cluster of
         * complex roots just past T left p 2.4e-18 of its size at T, the fma
         * sign said a crossing, and a false root was reported at T
         * (tests/runtime/test_hostile_fuzz.py, the cluster class). */
        int precise = sb != sa && kb == 0
                      && (j < nc || noise_holds(c, n, b, kb, vb, 0));
        double pb = 0;
        if (precise && at != NULL) {
            COUNT_MADDS(10 * n);
            pb = at->pb;
        } else if (precise) {
            pb = horner_compensated(c, n, b);
        }
        if (precise && pb != 0 && (pb > 0) == (sa > 0))
            sb = sa; /* no crossing in (a, b]: maybe a touch at b (below) */
        if (sb != sa) {
            *t = precise && j < nc
                     ? crossing_before_critical(c, d, n, a, b, sa, pb)
                     : refine_root(c, d[n - 1], n, a, b, sa, 0, split_point(a, b));
            *graze = 0;
            return 1;
        }
        /* (on a touch's interval, b is a minimum: touch_critical has p''
         * > 0 there; elsewhere a maximum is no touch: rises_to) */
        int near = 0;
        if (skin >= 0 && j < nc && at != NULL) {
            COUNT_MADDS(n); /* (noise_holds' horner_abs) */
            near = fabs(vb) <= noise_factor(n) * at->ab + skin; /* (kb = 0) */
        } else if (skin >= 0 && j < nc) {
            near = noise_holds(c, n, b, kb, vb, skin) && !rises_to(d[n - 1], n, a, b);
        }
        if (near) {
            /* touch or cross?  Look at the far end of the next piece. */
            double b2 = j + 1 < nc ? crit[j + 1] : T;
            kb = scale_exponent(b2, n);
            if (at != NULL && nc == 1) {
                COUNT_MADDS(n);
                vb = at->vhi;
            } else {
                vb = horner(c, n, b2, kb, 1);
            }
            vb_known = 1;
            int s2 = (vb > 0) - (vb < 0);
            /* (its sign too is noise where p is within its noise there:
             * the precise value decides, as above) */
            if (s2 != sa && kb == 0 && noise_holds(c, n, b2, kb, vb, 0)) {
                double p2 = horner_compensated(c, n, b2);
                if (p2 != 0 && (p2 > 0) == (sa > 0))
                    s2 = sa;
            }
            if (s2 == sa) {
                *t = touch_point(d, n, b, at);
                *graze = 1;
                return 1;
            }
        }
        a = b;
    }
    return 0;
}

/* First root in (lo, T] of c (degree n >= 3, normalised, c(lo) > 0): the
 * critical points, then scan_pieces.  x0: a critical point known to within
 * rounding (the guess's touch), or 0. */
NOINLINE static int derivative_method(const double c[], int n, double lo, double T,
                                      double x0, double skin, double *t, int *graze)
{
    PHASE(3);
    COUNT(7);
    double d[MAXN + 1][MAXN + 1], crit[MAXN];
    derivative_chain(c, n, d);
    int nc = critical_points(d, n, lo, T, x0, crit);
    return scan_pieces(c, d, n, lo, T, crit, nc, skin, NULL, t, graze);
}

/* The critical point of p in (lo, hi) around the guess's touch x, certified
 * in one pass, or 0 where the pass cannot tell (the derivative method then
 * settles (lo, hi] as before).  d[n - 1], d[n - 2]: p', p''.  At x, Horner's
 * chains give the Taylor coefficients f1 = p', f2 = p''/2, f3 = p'''/6, each
 * within e g_k of the exact one (e = noise_factor(n), twice gamma_{2n}),
 * where g_k = sum C(i, k) |p_i| hi^(i-k) bounds the k-th chain's terms for
 * 0 <= x <= hi; g4 bounds |p''''/24| on [0, hi].  So on [lo, hi] (h: the
 * farther end from x)
 *     p''/2 >= L = f2 - e g2 - 3 (|f3| + e g3) h - 6 g4 h^2,
 * and with L > 0, p' rises there by at least 2 L per unit: p'(lo) < 0 <
 * p'(hi) when |f1| + e g1 < 2 L (x - lo) and < 2 L (hi - x).  Then p is
 * convex on [lo, hi] with exactly one critical point, found as the
 * derivative method finds it: Newton on p' from x, the same first step
 * (p' and p'' from their coefficients), which ends it there when it is
 * within TOL_CRITICAL -- else 0 here, and the derivative method takes
 * the further steps.  (With |p'''| bounded by g3 over [0, hi] instead of by
 * its value at x, L was negative on 26 of the 184 touches of bench/roots.py's
 * grazes: g3 sums the terms' sizes, which cancel.)  This replaces, on the
 * touch's interval, the derivative method's p''', its convexity test and
 * the signs of p' at both ends, one after the other, by chains that run
 * side by side: the same critical point, bit for bit. */
/* Horner's chains for the Taylor certificates (touch_critical,
 * positive_through_the_noise, falls_through_the_noise): f[0..3] = p(x),
 * p'(x), p''(x)/2, p'''(x)/6, and at y >= |x| the sums of |terms| g[k] =
 * sum C(i, k) |c_i| y^(i-k), k = 0..4, that bound their rounding and, at
 * |z| <= y, the derivatives |p^(k)(z)| / k!. */
static inline void noise_chains(const double c[], int n, double x, double y, double f[4],
                                double g[5])
{
    double f0 = c[n], f1 = 0, f2 = 0, f3 = 0;
    double g0 = fabs(c[n]), g1 = 0, g2 = 0, g3 = 0, g4 = 0;
    for (int i = n - 1; i >= 0; i--) {
        f3 = f3 * x + f2;
        f2 = f2 * x + f1;
        f1 = f1 * x + f0;
        f0 = f0 * x + c[i];
        g4 = g4 * y + g3;
        g3 = g3 * y + g2;
        g2 = g2 * y + g1;
        g1 = g1 * y + g0;
        g0 = g0 * y + fabs(c[i]);
    }
    f[0] = f0; f[1] = f1; f[2] = f2; f[3] = f3;
    g[0] = g0; g[1] = g1; g[2] = g2; g[3] = g3; g[4] = g4;
}

/* From the chains at x (noise_chains; e = noise_factor(n), rel its
 * relative slack): a lower bound of p''/2 over [x - h, x + h] within
 * [-y, y], by Taylor from p''(x)/2 with |p'''(x)|/6 and the bound of
 * |p''''|/24 there. */
static inline double half_curvature_floor(const double f[4], const double g[5], double e,
                                          double rel, double h)
{
    return f[2] * (1 - rel) -
           (e * g[2] + 3 * (fabs(f[3]) + e * g[3]) * h + 6 * g[4] * h * h) * (1 + rel);
}

static double touch_critical(const double p[], double d[MAXN + 1][MAXN + 1],
                             int n, double lo, double hi, double x)
{
    /* (a bracket below TOL_CRITICAL would end refine_root before its
     * step: left to it) */
    if (!(lo >= 0 && lo < x && hi - x > TOL_CRITICAL * hi) || scale_exponent(hi, n) != 0)
        return 0;
    COUNT_MADDS(9 * n);
    double f[4], g[5];
    noise_chains(p, n, x, hi, f, g);
    double e = noise_factor(n), rel = 4.0 * (n + 1) * UNIT_ROUNDOFF;
    double h = x - lo > hi - x ? x - lo : hi - x;
    double L = half_curvature_floor(f, g, e, rel, h);
    double slope = (fabs(f[1]) + e * g[1]) * (1 + rel); /* >= |p'(x)| */
    if (!(L > 0 && slope < 2 * L * (x - lo) * (1 - rel) &&
          slope < 2 * L * (hi - x) * (1 - rel)))
        return 0;
    /* refine_root's first step on p' from x (tol TOL_CRITICAL), and its
     * stop */
    COUNT(4);
    double df, size, v = value_and_slope(d[n - 1], d[n - 2], n - 1, x, 0, 0, &df, &size);
    if (v == 0)
        return x;
    double b = x - v / df;
    return b > lo && b < hi && fabs(x - b) <= TOL_CRITICAL * fabs(b) ? b : 0;
}

/* ------------------------------------------------------------------ */
/* Interval solver                                                      */
/* ------------------------------------------------------------------ */

/* First root in (0, T] of p (degree n >= 3, normalised, p[0] > 0):
 * ISOLATED, SCANNED where the derivative method found it (its scan's fma
 * signs cannot see a crossing pair inside the noise: never_late looks
 * again), or 0 (none). */
static int first_root_interval(const double p[], int n, double T,
                               double skin, double failed_w, double *t, int *graze)
{
    double lo = 0;
    if (T <= (n <= 8 ? FAST_LIMIT_LOW : FAST_LIMIT_HIGH)) {
        int r = isolate_first_root(p, n, skin, T, failed_w, t, graze, &lo);
        if (r != UNRESOLVED)
            return r; /* (CLEARED is 0) */
    }
    return derivative_method(p, n, lo, T, 0, skin, t, graze) ? SCANNED : 0;
}

/* Degree-specialised copies of the solve for degrees 4 and 8 -- the
 * contact polynomials of two circles without and with orbits, which the
 * shipped equations give most -- made by the compiler: a wrapper that
 * calls the common code with n a constant and inlines every call below it
 * (flatten), so the copy's loops over the degree have fixed bounds and its
 * calls are gone.  The same operations in the same order: the same bits
 * (tests/runtime/test_build_variants.py builds with -DM2C_NO_DEGREE_CLONES
 * and compares).  The rare paths stay out of the copies (NOINLINE: the
 * derivative method, the sliced, GSL, closed and quadratic solvers), which
 * are 40 kB each for the interval part, 4.5 kB for the preparation.
 * Measured against the code without them (bench/roots_ab.py 837cda4
 * --sweeps 21 --cflags=-falign-functions=64, the median of 7 runs' ratios
 * of the medians: docs/performance-log.md): quartics 0.92, generic octics 0.93,
 * grazes 0.92, collision polynomials 0.89, no root in the window 0.83,
 * tmax = inf 0.93, complex roots near the window 0.98; --instructions
 * 0.86-0.96.  Degrees 12 and 16, copied alike, counted 0.91-0.93 of the
 * instructions but ran no faster (1.00-1.04): not copied.  The
 * preparation in solve() is copied the same way (solve_4, solve_8: a
 * further 0.94-0.98 of the time, measured with these), and for degree 2
 * (solve_2, whose solve is the closed form: 0.89 of the instructions,
 * 0.97 of the time). */
#if !defined(M2C_NO_DEGREE_CLONES) && defined(__has_attribute)
#if __has_attribute(flatten)
#define DEGREE_CLONES 1
#endif
#endif
#ifndef DEGREE_CLONES
#define DEGREE_CLONES 0
#endif

#if DEGREE_CLONES
#define INTERVAL_CLONE(N)                                                                \
    NOINLINE __attribute__((flatten)) static int first_root_interval_##N(               \
        const double p[], double T, double skin, double failed_w, double *t, int *graze) \
    {                                                                                    \
        return first_root_interval(p, N, T, skin, failed_w, t, graze);                  \
    }
INTERVAL_CLONE(4)
INTERVAL_CLONE(8)
#undef INTERVAL_CLONE

/* (out of line: the callers below are flattened, and the generic path must
 * not be copied into them) */
NOINLINE static int first_root_interval_any(const double p[], int n, double T,
                                            double skin, double failed_w, double *t,
                                            int *graze)
{
    return first_root_interval(p, n, T, skin, failed_w, t, graze);
}
#endif

/* first_root_interval, by its copy for the degree where there is one. */
static int first_root_interval_fixed(const double p[], int n, double T, double skin,
                                     double failed_w, double *t, int *graze)
{
#if DEGREE_CLONES
    if (n == 8)
        return first_root_interval_8(p, T, skin, failed_w, t, graze);
    if (n == 4)
        return first_root_interval_4(p, T, skin, failed_w, t, graze);
    return first_root_interval_any(p, n, T, skin, failed_w, t, graze);
#else
    return first_root_interval(p, n, T, skin, failed_w, t, graze);
#endif
}

/* ------------------------------------------------------------------ */
/* Extreme spreads                                                      */
/* ------------------------------------------------------------------ */

/* Coefficients spanning more than 2^MAX_SPREAD cannot all be normal numbers
 * after one scaling, and one substitution t = 2^k u cannot fix that for
 * roots of every magnitude.  So the window is cut into slices of t,
 * (2^d, 2^(d + SLICE)] with d a multiple of SLICE, scanned upwards from
 * Cauchy's lower bound on the roots, |c_0| / (|c_0| + max |c_i|) >
 * 2^(e_0 - e_max - 2); the first root found is the answer.  A slice where
 * one term beats each of the others by 2^6 at both ends beats their sum
 * over the whole slice (the exponents are linear in log2 t): no root, and
 * only integer work.  Any other slice is solved in u = t / 2^k, k = d +
 * SLICE / 2, over (2^(-SLICE/2), 2^(SLICE/2)], with the coefficients
 * c_i 2^(k i) scaled so the largest is in [1/2, 1) and those below DBL_MIN
 * dropped: in the slice a dropped term is below 2^(-1022 + 16 SLICE) =
 * 2^-510 of the largest term, far below rounding.  (The one-substitution
 * scheme this replaces dropped terms that decide roots elsewhere: 2-8 % of
 * the fuzz vectors at such spreads got a wrong root, tests/runtime/
 * test_extremes.py.)  Every method takes this path at such spreads. */
#define SLICE 32
#define DOMINANCE 6

/* The index of the term that beats every other by 2^DOMINANCE at t = 2^d,
 * or -1. */
static int dominant_term(const int e[], const int nz[], int n, int d)
{
    int best = -1, top = INT_MIN, second = INT_MIN;
    for (int i = 0; i <= n; i++) {
        if (!nz[i])
            continue;
        int v = e[i] + d * i;
        if (v > top) {
            second = top;
            top = v;
            best = i;
        } else if (v > second) {
            second = v;
        }
    }
    return second == INT_MIN || top - second >= DOMINANCE ? best : -1;
}

/* First root in (0, tmax] of c (degree n >= 1, c[0] != 0, unnormalised,
 * spread beyond MAX_SPREAD); skin as in solve() but in the units of c. */
NOINLINE static int first_root_sliced(const double c[], int n, double tmax, double eps,
                                      int nograze, double *t, int *graze)
{
    int e[MAXN + 1], nz[MAXN + 1], emax;
    exponents(c, n, e, nz, &emax);
    /* u in [2^(-SLICE/2), 2^(SLICE/2)]: the lower end is closed, so a root
     * that the slice below decided to be just beyond it (by a dropped term)
     * is found at it; lo_open is the largest double below it */
    const double lo = 0x1p-16, lo_open = 0x1.fffffffffffffp-17, hi = 0x1p16;
    for (int d = floor_div(e[0] - emax - 2, SLICE) * SLICE; d < DBL_MAX_EXP; d += SLICE) {
        if (d >= DBL_MIN_EXP - DBL_MANT_DIG && ldexp(1.0, d) >= tmax)
            return 0; /* the slices left are beyond tmax */
        int v = dominant_term(e, nz, n, d);
        if (v >= 0 && v == dominant_term(e, nz, n, d + SLICE))
            continue;
        int k = d + SLICE / 2, top = INT_MIN;
        for (int i = 0; i <= n; i++)
            if (nz[i] && e[i] + k * i > top)
                top = e[i] + k * i;
        double q[MAXN + 1];
        for (int i = 0; i <= n; i++) {
            q[i] = nz[i] ? ldexp(c[i], k * i - top - 1) : 0;
            if (fabs(q[i]) < DBL_MIN)
                q[i] = 0; /* also -0 -> 0 */
        }
        int m = n;
        while (m > 0 && q[m] == 0)
            m--;
        if (m == 0)
            continue;
        double tu = ldexp(tmax, -k);
        double T = tu < hi ? tu : hi;
        double skin = nograze ? -1 : eps == 0 ? 0 : ldexp(eps, -top - 1);
        double root = 0;
        int g = 0, found;
        if (m == 1) {
            root = -q[0] / q[1];
            found = root > lo_open && root <= T;
        } else if (m == 2) {
            found = first_root_quadratic(q, lo_open, T, skin, &root, &g);
        } else {
            int s = sign_at(q, m, lo, 1);
            for (int i = 0; i <= m && s < 0; i++)
                q[i] = -q[i];
            root = lo;
            found = s == 0 || derivative_method(q, m, lo, T, 0, skin, &root, &g);
        }
        if (found) {
            /* a root at or above half the least subnormal rounds up to it
             * (nearest, a tie up: never a miss); below that it underflows to
             * 0, not representable (status 0).  ldexp's own rounding of the
             * half way ties to 0: 5e-324 - 2 t + t^2 was "no root". */
            *t = ldexp(root, k);
            if (*t == 0 && root >= ldexp(1.0, DBL_MIN_EXP - DBL_MANT_DIG - 1 - k))
                *t = ldexp(1.0, DBL_MIN_EXP - DBL_MANT_DIG);
            *graze = g;
            return 1;
        }
    }
    return 0;
}

/* ------------------------------------------------------------------ */
/* Choosing among complex roots (GSL and closed methods)              */
/* ------------------------------------------------------------------ */

static int pick_first_real(const double zr[], const double zi[], int m,
                           double tmax, double *t, int *graze)
{
    int found = 0;
    double best = 0;
    int best_graze = 0;
    for (int i = 0; i < m; i++) {
        double x = zr[i], y = zi[i];
        if (!isfinite(x) || !isfinite(y))
            continue;
        if (fabs(y) > REAL_TOL * hypot(x, y))
            continue;
        if (!(x > 0 && x <= tmax))
            continue;
        if (!found || x < best) {
            found = 1;
            best = x;
            best_graze = y != 0;
        }
    }
    if (found) {
        *t = best;
        *graze = best_graze;
    }
    return found;
}

/* ------------------------------------------------------------------ */
/* GSL companion-matrix method                                          */
/* ------------------------------------------------------------------ */

#ifndef M2C_NO_GSL
NOINLINE static int first_root_gsl(const double c[], int n, double tmax, double *t,
                                   int *graze)
{
    double z[2 * MAXN], zr[MAXN], zi[MAXN];
    gsl_poly_complex_workspace *w = gsl_poly_complex_workspace_alloc((size_t)n + 1);
    if (w == NULL)
        return 0;
    /* GSL aborts on failures by default; a library must not do that. */
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    int st = gsl_poly_complex_solve(c, (size_t)n + 1, w, z);
    gsl_set_error_handler(old);
    gsl_poly_complex_workspace_free(w);
    if (st != GSL_SUCCESS)
        return 0;
    for (int i = 0; i < n; i++) {
        zr[i] = z[2 * i];
        zi[i] = z[2 * i + 1];
    }
    return pick_first_real(zr, zi, n, tmax, t, graze);
}
#else
/* Built without GSL: solve() refuses the method (-1) before this. */
NOINLINE static int first_root_gsl(const double c[], int n, double tmax, double *t,
                                   int *graze)
{
    (void)c; (void)n; (void)tmax; (void)t; (void)graze;
    return 0;
}
#endif

/* ------------------------------------------------------------------ */
/* Closed-form quartic (Orellana & De Michele, ACM TOMS Algorithm 1010) */
/* ------------------------------------------------------------------ */

/* Rescaling factors for over/underflowing quartics: DBL_MAX^(1/3) / phi and
 * DBL_MAX^(1/4) / phi (phi the golden ratio), as in the paper. */
#define CUBIC_RESCALE 3.488062113727083e+102
#define QUARTIC_RESCALE 7.156344627944542e+76

/* Largest-magnitude real root of x^3 + g x + h, written with Q = -g/3,
 * R = h/2 and the discriminant R^2 - Q^3 carried as a scaled K so that huge
 * g, h do not overflow. */
static double cubic_dominant_scaled(double g, double h)
{
    double Q = -g / 3, R = 0.5 * h, K;
    if (R == 0)
        return g <= 0 ? sqrt(-g) : 0;
    if (fabs(Q) < fabs(R)) {
        double qr = Q / R;
        K = 1 - Q * qr * qr; /* (R^2 - Q^3) / R^2 */
    } else {
        double rq = R / Q;
        K = copysign(1.0, Q) * (rq * rq / Q - 1); /* (R^2 - Q^3) / |Q|^3 */
    }
    if (K < 0) { /* three real roots (Q > 0): trigonometric form */
        double sq = sqrt(Q);
        double theta = acos(fmax(-1.0, fmin(1.0, (R / fabs(Q)) / sq)));
        return theta < PI_D / 2 ? -2 * sq * cos(theta / 3)
                                : -2 * sq * cos((theta + 2 * PI_D) / 3);
    }
    double A = fabs(Q) < fabs(R)
                   ? -copysign(cbrt(fabs(R) * (1 + sqrt(K))), R)
                   : -copysign(cbrt(fabs(R) + sqrt(fabs(Q)) * fabs(Q) * sqrt(K)), R);
    return A + (A == 0 ? 0 : Q / A);
}

/* Same root, Cardano/trigonometric form for moderate coefficients. */
static double cubic_dominant(double g, double h)
{
    double Q = -g / 3, R = 0.5 * h;
    if (fabs(Q) > 1e102 || fabs(R) > 1e154)
        return cubic_dominant_scaled(g, h);
    double Q3 = Q * Q * Q, R2 = R * R;
    if (R2 < Q3) {
        double theta = acos(fmax(-1.0, fmin(1.0, R / sqrt(Q3)))), s = -2 * sqrt(Q);
        return theta < PI_D / 2 ? s * cos(theta / 3)
                                : s * cos((theta + 2 * PI_D) / 3);
    }
    double A = -copysign(cbrt(fabs(R) + sqrt(R2 - Q3)), R);
    return A + (A == 0 ? 0 : Q / A);
}

/* phi0: dominant root of the resolvent cubic of the monic quartic
 * x^4 + a x^3 + b x^2 + c x + d, computed on the quartic shifted to its
 * inflection point (the resolvent variable is shift invariant), then
 * polished by Newton while the residual decreases. */
static double resolvent_phi0(double a, double b, double c, double d, int scaled)
{
    double disc = 9 * a * a - 24 * b, s;
    if (disc > 0) {
        disc = sqrt(disc);
        s = a > 0 ? -2 * b / (3 * a + disc) : -2 * b / (3 * a - disc);
    } else {
        s = -a / 4;
    }
    double as = a + 4 * s;
    double bs = b + 3 * s * (a + 2 * s);
    double cs = c + s * (2 * b + s * (3 * a + 4 * s));
    double ds = d + s * (c + s * (b + s * (a + s)));
    double gg = bs * bs / 9, hh = as * cs;
    double g = hh - 4 * ds - 3 * gg;
    double h = (8 * ds + hh - 2 * gg) * bs / 3 - cs * cs - ds * as * as;
    double x = cubic_dominant(g, h);
    if (!isfinite(x)) {
        x = cubic_dominant_scaled(g, h);
        if (!isfinite(x) && scaled) {
            /* rescale the depressed cubic too */
            double r = CUBIC_RESCALE, r2 = r * r;
            double a2 = as / r, b2 = bs / r, c2 = cs / r;
            double gg2 = b2 * b2 / 9, hh2 = a2 * c2, d2 = ds / r2;
            g = hh2 - 4 * d2 - 3 * gg2;
            h = (8 * d2 + hh2 - 2 * gg2) * b2 / 3 - c2 * (c2 / r) - (ds / r) * a2 * a2;
            x = cubic_dominant(g, h);
            if (!isfinite(x))
                x = cubic_dominant_scaled(g, h);
            x *= r;
        }
    }
    double f = x * (x * x + g) + h;
    double scale = fmax(fabs(x * x * x), fmax(fabs(g * x), fabs(h)));
    if (!(fabs(f) > DBL_EPSILON * scale))
        return x;
    for (int it = 0; it < 8; it++) {
        double df = 3 * x * x + g;
        if (df == 0)
            break;
        double xn = x - f / df;
        double fn = xn * (xn * xn + g) + h;
        if (fn == 0)
            return xn;
        if (!(fabs(fn) < fabs(f)))
            break;
        x = xn;
        f = fn;
    }
    return x;
}

/* Relative residual of a candidate factorisation (x^2 + p x + q)(x^2 + r x + s)
 * of x^4 + a x^3 + b x^2 + c x + d; include_d selects whether the constant
 * term is measured too. */
static double rel_err(double v, double ref)
{
    return ref == 0 ? fabs(v) : fabs((v - ref) / ref);
}

static double factor_error(double a, double b, double c, double d, double p,
                           double q, double r, double s, int include_d)
{
    double e = rel_err(q * r + p * s, c) + rel_err(q + p * r + s, b) +
               rel_err(p + r, a);
    return include_d ? e + rel_err(q * s, d) : e;
}

static double cfactor_error(double a, double b, double c, double d,
                            double complex p, double complex q,
                            double complex r, double complex s)
{
    double e = 0;
    e += d == 0 ? cabs(q * s) : cabs((q * s - d) / d);
    e += c == 0 ? cabs(q * r + p * s) : cabs((q * r + p * s - c) / c);
    e += b == 0 ? cabs(q + p * r + s) : cabs((q + p * r + s - b) / b);
    e += a == 0 ? cabs(p + r) : cabs((p + r - a) / a);
    return e;
}

/* Residual of the LDL^T decomposition parameters (paper eqs. 29-30). */
static double ldlt_error(double b, double c, double d, double d2, double l1,
                         double l2, double l3)
{
    return rel_err(d2 + l1 * l1 + 2 * l3, b) +
           rel_err(2 * d2 * l2 + 2 * l1 * l3, c) +
           rel_err(d2 * l2 * l2 + l3 * l3, d);
}

/* Newton on the four factor coefficients (p, q, r, s), x = (p,q,r,s), against
 * the residual of  q s = d,  q r + p s = c,  q + p r + s = b,  p + r = a;
 * stops when the summed relative residual stops decreasing. */
static void refine_factors(double a, double b, double c, double d, double x[4])
{
    const double ref[4] = {d, c, b, a};
    double fv[4], err = 0;
#define RESIDUALS()                                              \
    do {                                                         \
        fv[0] = x[1] * x[3] - d;                                 \
        fv[1] = x[1] * x[2] + x[0] * x[3] - c;                   \
        fv[2] = x[1] + x[0] * x[2] + x[3] - b;                   \
        fv[3] = x[0] + x[2] - a;                                 \
        err = 0;                                                 \
        for (int i = 0; i < 4; i++)                              \
            err += ref[i] == 0 ? fabs(fv[i]) : fabs(fv[i] / ref[i]); \
    } while (0)
    RESIDUALS();
    for (int it = 0; it < 8; it++) {
        double pr = x[0] - x[2];
        double det = x[1] * x[1] + x[1] * (-x[2] * pr - 2 * x[3]) +
                     x[3] * (x[0] * pr + x[3]);
        if (det == 0)
            break;
        /* adjugate of the Jacobian (rows: unknowns, columns: residuals) */
        double J[4][4];
        J[0][0] = pr;
        J[0][1] = x[3] - x[1];
        J[0][2] = x[1] * x[2] - x[0] * x[3];
        J[0][3] = -x[1] * J[0][1] - x[0] * J[0][2];
        J[1][0] = x[0] * J[0][0] + J[0][1];
        J[1][1] = -x[1] * J[0][0];
        J[1][2] = -x[1] * J[0][1];
        J[1][3] = -x[1] * J[0][2];
        J[2][0] = -J[0][0];
        J[2][1] = -J[0][1];
        J[2][2] = -J[0][2];
        J[2][3] = J[0][2] * x[2] + J[0][1] * x[3];
        J[3][0] = -x[2] * J[0][0] - J[0][1];
        J[3][1] = J[0][0] * x[3];
        J[3][2] = x[3] * J[0][1];
        J[3][3] = x[3] * J[0][2];
        double old[4], old_err = err;
        for (int i = 0; i < 4; i++) {
            double dx = 0;
            for (int j = 0; j < 4; j++)
                dx += J[i][j] * fv[j];
            old[i] = x[i];
            x[i] -= dx / det;
        }
        RESIDUALS();
        if (err == 0)
            break;
        if (err >= old_err) {
            for (int i = 0; i < 4; i++)
                x[i] = old[i];
            break;
        }
    }
#undef RESIDUALS
}

/* Roots of x^2 + p x + q (real p, q) as complex pairs. */
static void monic_quadratic_roots(double p, double q, double zr[2], double zi[2])
{
    double disc = p * p - 4 * q;
    if (disc >= 0) {
        double big = 0.5 * (p >= 0 ? -p - sqrt(disc) : -p + sqrt(disc));
        zr[0] = big;
        zr[1] = big == 0 ? 0 : q / big;
        zi[0] = zi[1] = 0;
    } else {
        zr[0] = zr[1] = -0.5 * p;
        zi[0] = 0.5 * sqrt(-disc);
        zi[1] = -zi[0];
    }
}

/* Given d2 < 0, the real factorisation (Case I of the paper), then the
 * coefficient of the smaller-|.| linear term recomputed from whichever of
 * the three equations fits best. */
static void real_factors(double a, double b, double c, double d, double l1,
                         double l2, double l3, double d2, double x[4])
{
    double gamma = sqrt(-d2);
    double p = l1 + gamma, q = l3 + gamma * l2;
    double r = l1 - gamma, s = l3 - gamma * l2;
    if (fabs(s) < fabs(q))
        s = d / q;
    else if (fabs(s) > fabs(q))
        q = d / s;
    double cand[3], best_err = INFINITY;
    int nc = 0;
    if (fabs(p) < fabs(r)) {
        if (s != 0) cand[nc++] = (c - q * r) / s;
        if (r != 0) cand[nc++] = (b - s - q) / r;
        cand[nc++] = a - r;
        for (int i = 0; i < nc; i++) {
            double e = factor_error(a, b, c, d, cand[i], q, r, s, 0);
            if (i == 0 || e < best_err) { best_err = e; p = cand[i]; }
        }
    } else {
        if (q != 0) cand[nc++] = (c - p * s) / q;
        if (p != 0) cand[nc++] = (b - q - s) / p;
        cand[nc++] = a - p;
        double r0 = r;
        for (int i = 0; i < nc; i++) {
            double e = factor_error(a, b, c, d, p, q, cand[i], s, 0);
            if (i == 0 || e < best_err) { best_err = e; r0 = cand[i]; }
        }
        r = r0;
    }
    x[0] = p; x[1] = q; x[2] = r; x[3] = s;
}

/* The four roots of c[4] x^4 + ... + c[0] (c[4] != 0), as (zr, zi). */
static void quartic_roots(const double cf[5], double zr[4], double zi[4])
{
    double a = cf[3] / cf[4], b = cf[2] / cf[4];
    double c = cf[1] / cf[4], d = cf[0] / cf[4];
    double rescale = 1;
    double phi0 = resolvent_phi0(a, b, c, d, 0);
    if (!isfinite(phi0)) {
        rescale = QUARTIC_RESCALE;
        double r2 = rescale * rescale;
        a /= rescale;
        b /= r2;
        c /= r2 * rescale;
        d /= r2 * r2;
        phi0 = resolvent_phi0(a, b, c, d, 1);
    }
    double l1 = a / 2, l3 = b / 6 + phi0 / 2;
    double del2 = c - a * l3;
    double d2_direct = 2 * b / 3 - phi0 - l1 * l1;
    double d3 = d - l3 * l3;

    /* Candidates for (d2, l2); keep the one with the least residual. */
    double d2c[3], l2c[3];
    int nc = 0;
    if (d2_direct != 0) {
        d2c[nc] = d2_direct;
        l2c[nc++] = del2 / (2 * d2_direct);
    }
    if (del2 != 0) {
        double l2 = 2 * d3 / del2;
        if (l2 != 0) {
            d2c[nc] = del2 / (2 * l2);
            l2c[nc++] = l2;
        }
        d2c[nc] = d2_direct;
        l2c[nc++] = l2;
    }
    double d2 = 0, l2 = 0, best = INFINITY;
    for (int i = 0; i < nc; i++) {
        double e = ldlt_error(b, c, d, d2c[i], l1, l2c[i], l3);
        if (i == 0 || e < best) { best = e; d2 = d2c[i]; l2 = l2c[i]; }
    }

    /* kind: 1 real factors, 0 complex-conjugate factors, -1 undecided */
    int kind;
    double x[4] = {0, 0, 0, 0};
    double complex cp = 0, cq = 0;
    if (d2 < 0) {
        real_factors(a, b, c, d, l1, l2, l3, d2, x);
        kind = 1;
    } else if (d2 > 0) {
        double gamma = sqrt(d2);
        cp = COMPLEX_OF(l1, gamma);
        cq = COMPLEX_OF(l3, gamma * l2);
        kind = 0;
    } else {
        kind = -1;
    }
    /* Case III: d2 (nearly) 0 -- compare with the d2 = 0 factorisation. */
    double tiny = DBL_EPSILON * fmax(fabs(2 * b / 3), fmax(fabs(phi0), l1 * l1));
    if (kind == -1 || fabs(d2) <= tiny) {
        double err0 = INFINITY;
        if (kind == 1)
            err0 = factor_error(a, b, c, d, x[0], x[1], x[2], x[3], 1);
        else if (kind == 0)
            err0 = cfactor_error(a, b, c, d, cp, cq, conj(cp), conj(cq));
        if (d3 <= 0) {
            double y[4] = {l1, l3 + sqrt(-d3), l1, l3 - sqrt(-d3)};
            if (fabs(y[3]) < fabs(y[1]))
                y[3] = d / y[1];
            else if (fabs(y[3]) > fabs(y[1]))
                y[1] = d / y[3];
            double err1 = factor_error(a, b, c, d, y[0], y[1], y[2], y[3], 1);
            if (kind == -1 || err1 < err0) {
                for (int i = 0; i < 4; i++)
                    x[i] = y[i];
                kind = 1;
            }
        } else {
            double complex p1 = l1, q1 = COMPLEX_OF(l3, sqrt(d3));
            double err1 = cfactor_error(a, b, c, d, p1, q1, conj(p1), conj(q1));
            if (kind == -1 || err1 < err0) {
                cp = p1;
                cq = q1;
                kind = 0;
            }
        }
    }
    if (kind == 1) {
        refine_factors(a, b, c, d, x);
        monic_quadratic_roots(x[0], x[1], zr, zi);
        monic_quadratic_roots(x[2], x[3], zr + 2, zi + 2);
    } else {
        /* (x^2 + cp x + cq)(x^2 + conj(cp) x + conj(cq)): roots pair up as
         * conjugates; the small one from the product of the roots. */
        double complex disc = csqrt(cp * cp / 4 - cq);
        double complex z1 = -cp / 2 + disc, z2 = -cp / 2 - disc;
        double complex zmax = cabs(z1) > cabs(z2) ? z1 : z2;
        double complex zmin = cq / zmax;
        zr[0] = creal(zmin); zi[0] = cimag(zmin);
        zr[1] = creal(zmin); zi[1] = -cimag(zmin);
        zr[2] = creal(zmax); zi[2] = cimag(zmax);
        zr[3] = creal(zmax); zi[3] = -cimag(zmax);
    }
    for (int i = 0; i < 4; i++) {
        zr[i] *= rescale;
        zi[i] *= rescale;
    }
}

/* Closed method for degree 3..4 (cubic as t * p(t), see header). */
NOINLINE static int first_root_closed(const double c[], int n, double tmax, double *t,
                                      int *graze)
{
    double q[5], zr[4], zi[4];
    if (n == 3) {
        q[0] = 0;
        for (int i = 0; i <= 3; i++)
            q[i + 1] = c[i];
    } else {
        for (int i = 0; i <= 4; i++)
            q[i] = c[i];
    }
    quartic_roots(q, zr, zi);
    return pick_first_real(zr, zi, 4, tmax, t, graze);
}

/* ------------------------------------------------------------------ */
/* Entry points                                                         */
/* ------------------------------------------------------------------ */

/* Step 0a' (see header): no root in (0, inf) by the AM-GM inequality,
 * where every negative coefficient of sign(c_0) c stands alone between two
 * positive ones, a t^(i-1) + b t^(i+1) >= 2 sqrt(a b) t^i for t > 0: a term
 * c_i t^i with |c_i| < 2 sqrt(a b) is outweighed by its neighbours, each
 * positive coefficient lending half of itself to each of two negative
 * neighbours (all of itself to one).  Shown for the envelope q (p's
 * positive coefficients less, its negative ones more, by the noise factor
 * e, here taken twice so that no computed graze test can see a touch
 * where this sees none): q > 0 on (0, inf), nothing there, as the full
 * path would conclude -- at the cost of a few comparisons and square
 * roots.  Descartes (step 0a) is the case of no negative coefficient at
 * all; with a sign change between c_0 and c_n there is a root, and the
 * test fails at once.  The rounding of the comparison (the square roots,
 * their product, a halving) is within the factor K, and neither side can
 * overflow to a wrong answer (an infinite right side is a true one).
 * Only with tmax = inf, where the window's first test at 0 (step 0b)
 * needs the preparation first: on bench/roots.py's "no root, tmax = inf"
 * family it settles 20 of the 135 solves that Descartes leaves. */
static int outweighed(const double c[], int n)
{
    double s = c[0] < 0 ? -1 : 1, e = 2 * noise_factor(n);
    double K = (1 + e) / (1 - e) * (1 + 16 * UNIT_ROUNDOFF);
    if (!(s * c[n] > 0))
        return 0;
    /* The signs of s c_i as bit masks (bit i), then the pattern in one
     * test -- every negative coefficient's two neighbours positive (not a
     * zero, not two negatives side by side) -- and the comparison of each
     * negative one, visited by its bit, with no exit at a failure: the
     * same conditions as a loop over every i with a branch on each sign and
     * an exit at the first failure, without those branches, whose outcomes
     * are data (measured against that loop, bench/roots_ab.py dc8ae46
     * --sweeps 21, aligned, two runs: "tmax = inf" 0.86 and 0.95 of the time
     * at the median, 1.01 in the mean, as a window it does not settle now
     * reads every sign first; generic octics 1.02; --instructions 1.005-1.012
     * on the families that reach it; the same answers: docs/performance-log.md).
     * (s c_0 > 0 and s c_n > 0: no negative at either end, so each has both
     * neighbours.) */
    uint32_t neg = 0, pos = 0;
    for (int i = 0; i <= n; i++) {
        double v = s * c[i];
        neg |= (uint32_t)(v < 0) << i;
        pos |= (uint32_t)(v > 0) << i;
    }
    if (((neg << 1) | (neg >> 1)) & ~pos)
        return 0; /* a zero, or two negatives side by side */
    int ok = 1;
    for (uint32_t m = neg; m != 0; m &= m - 1) {
#if defined(__GNUC__)
        int i = __builtin_ctz(m); /* the lowest negative left */
#else
        int i = 0;
        while (!((m >> i) & 1))
            i++;
#endif
        double v = s * c[i];
        double a = s * c[i - 1], b = s * c[i + 1];
        /* a lends to i - 2 too when that is negative, b to i + 2 */
        a *= 1 - 0.5 * (double)(((neg << 2) >> i) & 1);
        b *= 1 - 0.5 * (double)((neg >> (i + 2)) & 1);
        ok &= -v * K < 2 * (sqrt(a) * sqrt(b));
    }
    return ok;
}

/* Step 0b (see header): no root in (0, tmax] by the bounds of
 * clearly_positive at 0 over the whole of [0, tmax], on the coefficients as
 * given, before the preparation -- which, with the Point it fills, is most
 * of the cost of a solve that this test settles.  The lower bounds L_k are
 * those point_at_zero and clearly_positive form from p = c 2^-E sign(c_0)
 * (normalise's exact scaling), bit for bit.  Only where reduce would keep
 * every term (the exponents show it) and the spread is in range, so that
 * the polynomial tested is the one the full path solves; any window
 * [0, w] may be tested, so that its bound B on the roots is not needed.
 * Where it fails, the full path runs as before (then with w = min(tmax,
 * B), which may clear what this did not).  Returns 1 (no root), 0 (the test
 * failed) or -1 (not tried). */
NOINLINE static int cleared_at_once(const double c[], const int e[],
                                    const int nz[], int n, double tmax, Scan sc)
{
    int E = sc.emax + 1;
    if (!nz[n] || sc.emax - sc.emin > MAX_SPREAD || E < DBL_MIN_EXP ||
        E > DBL_MAX_EXP - 2 || !leading_far(e, nz, n, tmax, sc.emax))
        return -1;
    double f = (c[0] < 0 ? -1 : 1) * pow2(-E), en = noise_factor(n);
    double qt[MAXN + 1], tol[MAXN + 1];
    for (int k = 0; k <= n; k++) {
        double p = c[k] * f;
        qt[k] = p - en * fabs(p);
        tol[k] = DBL_EPSILON * fabs(p);
    }
    return bounds_positive(qt, tol, n, tmax, 1);
}

/* Which side of the rounding band x is on, for p = c_0..c_n plus the
 * terms reduce dropped, tail[j] x^(n+1+j) (m of them, scaled as c): p's
 * own by compensated Horner (its error within u |v| + gamma_{2n}^2 sum
 * |c_i| x^i, Graillat, Langlois & Louvet), the tail's -- at most 4 degree
 * eps of the rest there -- by plain Horner (within 2 gamma_{2(n+m)} of its
 * sum of |terms|), all taken twice: 1 where p(x) > 0 certainly (p(0) > 0
 * after normalise: nothing there), -1 where p(x) < 0 certainly (past a
 * crossing), 0 within the band. */
static int band_side(const double c[], int n, const double tail[], int m, double x)
{
    double g = 0.5 * noise_factor(n); /* gamma_{2n} */
    double v = horner_compensated(c, n, x);
    double a = horner_abs(c, n, x, 0);
    double et = 0;
    if (m > 0) {
        double xp = x, tv = tail[m - 1], ta = fabs(tail[m - 1]);
        for (int i = 0; i < n; i++)
            xp *= x; /* x^(n+1) */
        for (int j = m - 2; j >= 0; j--) {
            tv = tv * x + tail[j];
            ta = ta * x + fabs(tail[j]);
        }
        v += tv * xp;
        et = noise_factor(n + m) * (ta * xp);
    }
    double eb = 2 * (UNIT_ROUNDOFF * fabs(v) + g * g * a) + et;
    return v > eb ? 1 : v < -eb ? -1 : 0;
}

/* The coefficients of p(x + w u) in u (w a power of two): Horner's Taylor
 * shift in double-double (each product split by fma, each sum by two_sum),
 * rounded once at the end, so that near a cluster they keep what plain
 * arithmetic cancels away (inside_the_noise). */
static void shift_dd(const double c[], int n, double x, double w, double q[])
{
    double hi[MAXN + 1], lo[MAXN + 1];
    for (int i = 0; i <= n; i++) {
        hi[i] = c[i];
        lo[i] = 0;
    }
    for (int k = 0; k < n; k++) {
        for (int i = n - 1; i >= k; i--) {
            double ph = hi[i + 1] * x;
            double pl = fma(hi[i + 1], x, -ph) + lo[i + 1] * x;
            double sh = hi[i] + ph, bb = sh - hi[i];
            double se = (hi[i] - (sh - bb)) + (ph - bb);
            se += lo[i] + pl;
            hi[i] = sh + se;
            lo[i] = se - (hi[i] - sh);
        }
    }
    double f = 1;
    for (int k = 0; k <= n; k++) {
        q[k] = (hi[k] + lo[k]) * f;
        f *= w;
    }
}

/* inside_the_noise's shortcut for the common near miss, a double root's:
 * p certainly positive on [r - h, r] and above the fma noise at r - h, so
 * no root hides in the noise to the left of the touch r.  From Horner's
 * chains at r (noise_chains), p's compensated value less its error (m),
 * and Taylor's bound p(r - s) >= m - S s + L s^2 over [0, h], with S >=
 * |p'(r)| and L a lower bound of p''/2 there; h twice where the quadratic
 * leaves the noise. */
static int positive_through_the_noise(const double c[], int n, double r)
{
    double f[4], gs[5];
    noise_chains(c, n, r, r, f, gs);
    double e = noise_factor(n), rel = 4.0 * (n + 1) * UNIT_ROUNDOFF, g = 0.5 * e;
    double v = horner_compensated(c, n, r);
    double m = v - 2 * (UNIT_ROUNDOFF * fabs(v) + g * g * gs[0]); /* p(r) >= m */
    double S = (fabs(f[1]) + e * gs[1]) * (1 + rel);              /* >= |p'(r)| */
    double N = e * gs[0] * (1 + rel); /* >= the fma noise anywhere in [0, r] */
    if (!(m > 0 && f[2] > 0))
        return 0;
    double h = (S + sqrt(S * S + 4 * f[2] * N)) / f[2];
    double L = half_curvature_floor(f, gs, e, rel, h);
    return h < r && L > 0 && S * S < 4 * L * m * (1 - rel)
           && (m - S * h + L * h * h) * (1 - rel) > N;
}

/* inside_the_noise's shortcut for a crossing r the derivative method's
 * scan found, the common case: p' certainly negative on [r - h, r] and p
 * above the fma noise at r - h, so p falls monotonely through the noise
 * left of r and no crossing pair hides in it (never_late settles the one
 * root there).  From the chains at r (noise_chains), signed: m <= p(r)
 * (the plain chain less its noise: no compensated evaluation), D <=
 * -p'(r) and L <= p''/2 over [r - h, r] (as positive_through_the_noise
 * has it), so -p'(r - s) >= D + 2 L s and p(r - s) >= m + D s + L s^2 for
 * s in [0, h]; h twice where that quadratic leaves the noise.  Signed, so
 * that the first root of a near-double pair passes (L > 0 there: bounding
 * |p''| instead failed all 115 such crossings of bench/roots.py's graze8).
 * Fails, as it should, where p' is within its own noise: a cluster's. */
static int falls_through_the_noise(const double c[], int n, double r)
{
    double f[4], gs[5];
    noise_chains(c, n, r, r, f, gs);
    double e = noise_factor(n), rel = 4.0 * (n + 1) * UNIT_ROUNDOFF;
    double N = e * gs[0] * (1 + rel); /* >= the fma noise anywhere in [0, r] */
    double m = f[0] - N;              /* p(r) >= m (the chain's own noise) */
    double D = -(f[1] + e * gs[1]) * (1 - rel); /* <= -p'(r) */
    if (!(D > 0 && N > m))
        return 0;
    double k = f[2] > 0 ? f[2] : 0;
    double h = 4 * (N - m) / (D + sqrt(D * D + 4 * k * (N - m)));
    double L = half_curvature_floor(f, gs, e, rel, h);
    double low = L < 0 ? L : 0;
    return h < r && D + 2 * low * h * (1 + rel) > 0 && (m + D * h + L * h * h) * (1 - rel) > N;
}

/* A touch r where p is certainly positive (compensated), found only because
 * its fma value was within the noise there (touch = 1), or a crossing r
 * that the derivative method's scan found by fma signs (touch = 0).  Inside
 * that noise the scan cannot see a cluster's crossings: a quartic cluster
 * (the hostile fuzz at WINDOW_FUZZ_COUNT=20000) had its exact first root
 * 5.3e-8 before 1 and the touch at 1 + 7.6e-6; a quintic one its first
 * root at 1 - 1.7e-4 and the scan's crossing at 1 + 1.7e-4, the two roots
 * before it in the noise.  So p is solved again from where the noise
 * begins to its left, x_b (steps to the left, doubling, to the first point
 * outside it, where p is certainly positive), after a shift of p to x_b in
 * double-double (shift_dd), over (x_b, r): its first root if it has one,
 * else the answer as it was.  Not where Taylor's bounds at r show that
 * nothing hides there: a near miss of a double root keeps its touch
 * (positive_through_the_noise), a crossing where p falls through the
 * noise its root (falls_through_the_noise). */
static void band_walk(const double c[], int n, const double tail[], int m, double r,
                      double d, int hs, double *root, int *g);

NOINLINE static void inside_the_noise(const double c[], int n, int touch, double *root,
                                      int *g)
{
    double r = *root;
    if (scale_exponent(r, n) != 0 ||
        (touch ? positive_through_the_noise(c, n, r) : falls_through_the_noise(c, n, r)))
        return;
    double step = r * 0x1p-50, xb;
    for (;;) {
        step *= 2;
        xb = r - step;
        if (!(xb > 0) || step > r * 0x1p-4)
            return;
        if (!within_noise(c, n, xb, 0))
            break;
    }
    if (!(sign_at(c, n, xb, 1) > 0))
        return; /* (not a near miss: left to never_late's steps) */
    double w = r - xb, q[MAXN + 1] = {0};
    int e = ilogb(w) + 1;
    shift_dd(c, n, xb, ldexp(1.0, e), q);
    int eq[MAXN + 1], nz[MAXN + 1], emax;
    if (!(q[0] > 0) || exponents(q, n, eq, nz, &emax) > MAX_SPREAD)
        return;
    normalise(q, n, emax, 1.0);
    double u, t;
    int gu;
    if (!first_root_interval(q, n, ldexp(w, -e), 0, 0, &u, &gu))
        return;
    t = xb + ldexp(u, e);
    if (!(t < r))
        return;
    /* q's doubles are p shifted and rounded once: near a cluster that rounding
     * moves q's roots by far more than p's own band (the fourth vector of
     * INSIDE_THE_NOISE: 2.1e-13 late), so t is held to p's compensated band as
     * never_late holds a root (no second look inside the noise). */
    double d = t * 0x1p-50;
    int hs = band_side(c, n, NULL, 0, gu ? t : t - d);
    if (gu ? hs == -1 : hs != 1)
        band_walk(c, n, NULL, 0, t, d, hs, &t, &gu);
    *root = t;
    *g = gu;
}

/* Never later than the first root (issue 33, item 11).  Inside a cluster's
 * rounding band the polish can settle on a later root of the cluster, or on
 * a point where the plain sign was noise, and a touch found at a critical
 * point can follow a real crossing within the band.  A root (not a touch)
 * stands when p is certainly positive just before it, at r (1 - 2^-50):
 * one compensated evaluation, and almost always so (kappa below about
 * 1 / (n^2 u)).  A touch stands unless p is certainly negative at it: p
 * falls monotonely to it (the piece before it), so only then can a
 * crossing lie before it (an exact multiple root, (t - 1000)^4, stays
 * where it is).  Otherwise the earliest point that cannot be excluded is
 * the answer: steps to the left, doubling, until p is certainly positive,
 * then bisection between that and the last point that was not, until they
 * are r 2^-50 apart; reported as a crossing where p is certainly negative
 * there, else as a touch.  "Certainly" is for the polynomial as given: the
 * m leading terms reduce dropped (tail) are evaluated with it.  (Windows
 * beyond 2^60 are left as they are: compensated Horner is unscaled.) */
static void never_late(const double c[], int n, const double tail[], int m, double *root,
                       int *g)
{
    double r = *root;
    if (!(r > 0 && r <= 0x1p60))
        return;
    double d = r * 0x1p-50; /* (exact, as ldexp: no library call) */
    if (!(d > 0))
        return; /* (r below 2^-1024: the steps would not move) */
    double before = r - d;
    int hs = band_side(c, n, tail, m, *g ? r : before);
    if (*g && hs == 1 && n >= 3 && m == 0) {
        inside_the_noise(c, n, 1, root, g);
        return;
    }
    if (*g ? hs != -1 : hs == 1)
        return;
    band_walk(c, n, tail, m, r, d, hs, root, g);
}

/* never_late's steps from a root r that does not stand (d = r 2^-50, hs p's
 * band side at r - d for a crossing, at r for a touch): out of line, rarely
 * taken. */
NOINLINE static void band_walk(const double c[], int n, const double tail[], int m, double r,
                               double d, int hs, double *root, int *g)
{
    double hi = *g ? r : r - d, lo = 0, step = 2 * d;
    for (;;) {
        double x = r - step;
        if (!(x > 0))
            break; /* lo = 0: p(0) > 0 */
        int s = band_side(c, n, tail, m, x);
        if (s == 1) {
            lo = x;
            break;
        }
        hi = x;
        hs = s;
        step *= 2;
    }
    while (hi - lo > d) { /* (to d: what a root that stands may be late by) */
        double mid = lo + 0.5 * (hi - lo);
        if (!(mid > lo && mid < hi))
            break;
        int s = band_side(c, n, tail, m, mid);
        if (s == 1) {
            lo = mid;
        } else {
            hi = mid;
            hs = s;
        }
    }
    *root = hi;
    *g = hs != -1;
}

/* never_late with the m terms reduce dropped (dropped[], as given), scaled
 * as c was: by sign 2^-E.  (Out of line: rare, and its array kept out of
 * the common path.) */
NOINLINE static void late_with_tail(const double c[], int n, const double dropped[], int m,
                                    double sign, int E, double *root, int *g)
{
    double tail[MAXN] = {0};
    for (int j = 0; j < m; j++)
        tail[j] = ldexp(sign * dropped[j], -E);
    never_late(c, n, tail, m, root, g);
}

/* never_late for a root the derivative method found (SCANNED), with no
 * terms dropped: a crossing there is then looked for again inside the fma
 * noise to its left (inside_the_noise), from where it stands or where
 * never_late's steps left it -- where those steps can run (r 2^-50 > 0,
 * r <= 2^60).  (Out of line, never_late unchanged: with a flag of its own
 * for this, bench/roots_ab.py HEAD --instructions counted generic4 1.007,
 * noroot8 1.005, which never come here.) */
NOINLINE static void late_scanned(const double c[], int n, double *root, int *g)
{
    int crossing = !*g && n >= 3;
    never_late(c, n, NULL, 0, root, g);
    double r = *root;
    if (crossing && r <= 0x1p60 && r * 0x1p-50 > 0)
        inside_the_noise(c, n, 0, root, g);
}

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
    if (n == 1) {
        *root = -c[0] / c[1];
        return *root > 0 && *root <= tu;
    }
    if (n == 2)
        return first_root_quadratic(c, 0, tu, skin, root, g);
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
    if (skin == 0 && m == 0 && found != SCANNED)
        never_late(c, n, NULL, 0, root, g);
    else if (skin == 0 && m == 0)
        late_scanned(c, n, root, g);
    else if (skin == 0)
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
    if (sp > MAX_SPREAD)
        found = first_root_sliced(c, n, tmax, eps,
                                  method == M2C_METHOD_INTERVAL_NOGRAZE, &root, &g);
    else {
        int m = 0;
        const double *dropped = n == degree ? c_in : dropped_terms(c_in, degree, n, &m);
        found = solve_normalised(c, e, nz, n, emax, tmax, method, eps, failed_w, bound,
                                 dropped, m, &root, &g);
    }
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
