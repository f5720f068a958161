/*
 * max2code_roots.h -- time of next collision: the smallest root in (0, tmax]
 * of a real polynomial  c[0] + c[1] t + ... + c[degree] t^degree,  degree <= 16.
 *
 * Plain C11 functions with int/double/pointer arguments only, so that the
 * header works from generated `static` C code and from Modula-2 through a
 * DEFINITION MODULE FOR "C".  A program compiles runtime/c/max2code_roots.c and
 * links -lgsl -lgslcblas -lm (GSL is used only by M2C_METHOD_GSL; compiled with
 * -DM2C_NO_GSL it needs only -lm, and M2C_METHOD_GSL is then invalid input, -1).
 *
 * Contract (all functions)
 *   return  1  a root was found: 0 < *t <= tmax, *t finite, *t set;
 *           0  no root in (0, tmax] -- also when the first root is not
 *              representable: it underflows to 0 (say 1e-400) or overflows
 *              (beyond DBL_MAX, only with tmax = +INFINITY);
 *          -1  invalid input: a NaN/Inf coefficient, degree outside 0..16,
 *              tmax NaN or <= 0, a contact skin eps NaN, < 0 or infinite,
 *              or a NULL pointer.
 *   *t (and *graze) are written only when 1 is returned.
 *   tmax may be +INFINITY: no upper limit.
 *   An identically zero polynomial (bodies touching forever) gives 0.
 *
 * Preparation shared by every method
 *   1. Leading coefficients that are exactly 0 are dropped.
 *   2. If c[0] == 0 exactly (the bodies touch now), the polynomial is divided
 *      by t: we want the next root strictly after 0.
 *   3. A leading coefficient is dropped when it is negligible over the
 *      window [0, T]:  |c_n| T^n <= 4 n DBL_EPSILON max_{i<n} |c_i| T^i,
 *      with T = tmax.  With tmax = +INFINITY, T = K, the bound on the
 *      positive roots of the polynomial as it stands: Kioustelidis'
 *      2 max |c_i / c_n|^(1/(n-i)) over the c_i of the sign opposite to c_n's
 *      (with a contact skin eps > 0 and a graze check, Fujiwara's: over
 *      every c_i), each ratio rounded up to a power of two; once a term is
 *      dropped the window is
 *      (0, K]: roots of the rest beyond K are none of the polynomial's.  Over
 *      (0, K] the leading term is at least twice each term of the other sign,
 *      so it is dropped only beside a term of its own sign, and no root it
 *      makes is lost (1e-16 + t - 4.905 t^2 has its root 0.2039 with
 *      tmax = inf as with tmax = 10; until issue 33 T was the bound of the
 *      rest c_0..c_{n-1}, whose own root -1e-16 made the t^2 term look
 *      negligible, and the root was lost), while -4.5 + 3.75 t + 3 t^2 +
 *      3e-30 t^3 drops its cubic term (its other roots lie near -1e30, and
 *      kept, they cost the companion matrix of M2C_METHOD_GSL the root
 *      0.75).  There is no absolute threshold anywhere.
 *   Steps 1-3 repeat until nothing changes; then the coefficients are scaled
 *   by a power of two (exact) so that the largest has magnitude in [1/2, 1).
 *   4. Extremes only: when the nonzero coefficients span more than 2^1021
 *      (some would fall below DBL_MIN after that scaling), no one scaling
 *      serves roots of every magnitude.  Then (0, tmax] is cut into slices
 *      (2^d, 2^(d+32)] of t (d a multiple of 32, from Cauchy's lower bound
 *      on the roots upwards); a slice where one term beats each other by 2^6
 *      at both ends holds no root and is skipped; any other is solved in
 *      u = t / 2^(d+16) over [2^-16, 2^16] by the derivative method (below;
 *      closed forms for degree 1 and 2), with the coefficients c_i 2^(k i)
 *      scaled exactly and the terms below DBL_MIN dropped: in the slice such
 *      a term is below 2^-510 of the largest, far below rounding.  The first
 *      root found is the answer, whatever the method.  Tolerance, checked
 *      against an exact integer-arithmetic oracle on the adversarial vectors
 *      of tests/runtime/fuzz.py (tests/runtime/test_extremes.py): the first
 *      root within max(2^-40, 64 n u kappa) relative (kappa its condition
 *      number; at ordinary spreads the root is good to about an ulp), a
 *      touch only where |p| is within 2^-40 of sum |c_i| t^i (or the skin),
 *      no miss of a root that is representable and located within itself
 *      (64 n u kappa < 1).
 *      Steps 1-3 compare |c_n| T^(n-i) with 4 n eps |c_i| in exponents where
 *      a side would leave the double range (T^2 underflowing to 0 made every
 *      leading term look negligible).
 *   All four runtimes (C, Rust, Python, Modula-2) do exactly this.
 *
 * Methods
 *   M2C_METHOD_INTERVAL (default)  interval solver with a graze check.
 *     Window: (0, T], T = min(tmax, B) with B Kioustelidis' bound on the
 *     positive roots, 2 max |c_i / c_n|^(1/(n-i)) over the c_i of the sign
 *     opposite to c_n's (rounded up to a power of two as above); with a
 *     contact skin eps > 0, the Fujiwara bound over every c_i.
 *     The first event is the first root, or an earlier touch: a critical
 *     point x where |p(x)| <= 2 gamma_{2n} sum |c_i||x|^i (the standard
 *     Horner rounding bound, gamma_k = k u / (1 - k u), u = 2^-53, times a
 *     safety factor 2) and p has the same sign on both neighbouring pieces;
 *     a touch is reported as a (double) root with *graze = 1.  Both can only
 *     lie where the envelope q = p - sign(p(0)) 2 gamma_{2n} sum |c_i| t^i
 *     has changed sign.
 *     0. No sign change in c as given (zeros skipped), c[0] != 0 and no
 *        skin: no root (Descartes), before any of the preparation above.
 *        Nor, with tmax = +INFINITY, no skin and degree >= 3, where every
 *        negative coefficient of sign(c_0) c stands alone between two
 *        positive ones a and b with |c_i| (1 + e) / (1 - e) < 2 sqrt(a b)
 *        (e twice the noise factor; a positive coefficient with two
 *        negative neighbours lends half of itself to each): the neighbours
 *        outweigh it for every t > 0 (AM-GM), so q > 0 on (0, inf).
 *        Else, with tmax finite, no skin, degree >= 3 and the preparation
 *        bound to keep every term (the exponents show it): d's lower bound
 *        on q from its Taylor coefficients at 0 -- q(0) beats every
 *        negative term, to first or second order -- over all of [0, tmax],
 *        on c scaled as below; it holds: no root, before the rest of the
 *        preparation (which the interval methods then start with that
 *        bound over [0, T], unless T = tmax: the same test).
 *     1. Exclusion and isolation (T <= 2^100), cheapest first:
 *        a. A guess, then a certificate: Laguerre's method from 0, each step
 *           to the right (for real roots it converges monotonically to the
 *           first root after its start, cubically near it; complex roots in
 *           the way, a double root or no step to the right end the guess);
 *           once it converges to r (a step below 2^-26, or below 2^-14
 *           and 1/16 of the step before), Descartes' rule in the Bernstein basis
 *           on (0, r (1 + 2^-20)] (the sign changes of the Bernstein
 *           coefficients of p and q there, from the Taylor coefficients at
 *           0 by n rounds of running sums, each sign trusted only beyond an
 *           error bound) must find one change each, which makes r the first
 *           root (else the guess is dropped).  A step that lands past a
 *           root (p < 0 at the new x: complex roots near the first real
 *           one) ends the guess too: the same test on (0, x (1 + 2^-20)],
 *           and the polish starts inside the step; where complex roots
 *           leave Laguerre no real step and p falls, a Newton step takes
 *           its place (twice at most).  A touch ahead shows as
 *           Laguerre's linear convergence (3 step ratios in a row in [0.25,
 *           0.31]: 0.284 at degree 8 for a double root); the guess then
 *           goes to the critical point c by Newton on p', and keeps it
 *           where p(c) is within 2^20 times the rounding bound (see c).
 *        b. Descartes on (0, T] in the Bernstein basis, the same test on the
 *           whole window: q's coefficients all positive: no root; one
 *           change each: one simple root of p (with nothing before it but,
 *           possibly, a stretch where p stays within the noise): polished.
 *        c. A touch from a (tried before b, which a touch leaves
 *           undecided): where q's Bernstein coefficients on (0, c (1 -
 *           2^-10)] are all certainly positive (nothing before it),
 *           (c (1 - 2^-10), c (1 + 3 2^-10)] is settled: where a bound
 *           from p's Taylor coefficients at c shows p convex there with p'
 *           changing sign, the derivative method's Newton step on p' from
 *           c gives the one critical point and its scan of the two
 *           monotone pieces the answer (touch_critical); else the
 *           derivative method (step 2), its Newton for the critical point
 *           starting at c.  If nothing is found there, e goes on from the
 *           right end.  With the graze check only.
 *        d. Exclusion by halving: when q's signs are certain with an even
 *           count on the window (b), the window is halved in the
 *           Bernstein basis (de Casteljau) until every piece has q's
 *           coefficients all positive -- no root -- or a piece is in doubt
 *           (then on to e).  This is what clears windows with complex roots
 *           close to the axis.  Where the guess (a) gave up on complex roots
 *           in the way, the first split is at the dip of p it was heading
 *           for (one Newton step on p'), when that is well inside (1/16 of
 *           the window from either end): both sides then start where p is
 *           least.  The same point is e's first split.
 *        e. Budan-Fourier counts of the roots of p and of q in subintervals
 *           of (0, T] (sign changes of the Taylor coefficients, each trusted
 *           only beyond its rounding bound; any doubt goes to step 2), plus
 *           a lower bound on q from the Taylor coefficients at an end of the
 *           interval, and test b where a count is odd.  An interval where q
 *           has no root is cleared; one where p and q have exactly one root
 *           each is polished; otherwise the leftmost interval is bisected,
 *           up to 40 times in all and down to 2^-20 relative width.
 *        Two roots by both counts in an interval within a quarter of its
 *        right end (once per solve): a double root (a touch) or a close
 *        pair, which bisection would only approach by halving; it goes to
 *        step 2 at once.  A tangent at a that meets 0 within 2^-20 of a puts
 *        the next split just beyond that, for the same reason.
 *        Only certified signs decide; a to d only decide sooner.
 *     2. An interval the counts do not resolve (a double root, a tight
 *        cluster, a sign too close to call) goes to the derivative method,
 *        which handles the whole window when it exceeds 2^100 or when step
 *        1 cannot start or go on: Yuksel (HPG 2022) style -- the roots of
 *        the derivatives in the interval, found recursively (to 2^-28
 *        relative, those of p' to 2^-36 -- or until a Newton step is
 *        below 32 ulps, the rounding noise: they only bracket, and p' = 0
 *        makes p insensitive to them; where p'' is certainly positive on the
 *        interval -- beyond the rounding of its value anywhere there -- the
 *        roots of p' alone, the levels below being moot), split it into
 *        monotone pieces, scanned left
 *        to right with the graze check at each critical point (a touch is
 *        reported there after one more Newton step on p' with compensated
 *        Horner, kept when it is within the noise).  At a
 *        critical point the fma sign of p may be noise: a crossing before
 *        it counts only if compensated Horner confirms the sign (else the
 *        graze check runs there), and Newton towards it starts where
 *        p(b) + p''(b) (x - b)^2 / 2 meets 0.  If it finds nothing there,
 *        step 1 goes on to the right of the interval.
 *     Polishing: safeguarded Newton (bisection -- geometric when the bracket
 *     spans decades -- whenever Newton leaves the bracket or stalls) with
 *     plain Horner down to a step of 2^-26, then one or two steps with
 *     compensated Horner (Graillat, Langlois & Louvet; error-free products
 *     by fma where it is an instruction -- on x86-64 chosen at run time by
 *     the CPU, with the same bits -- else Dekker's splitting): the root
 *     is then correct to about an ulp unless its condition number nears
 *     1/u -- also roots near 1e-12, and moderately ill-conditioned ones
 *     (plain or FMA Horner would leave n u kappa).  Beyond 2^100 FMA Horner
 *     with power-of-two scaling.
 *     Never later than the first root (issue 33, item 11), with a contact
 *     skin or without: a root r of steps 1-2 stands where p is certainly positive just
 *     before it, at r (1 - 2^-50), and a touch unless p is certainly
 *     negative at it (p falls monotonely to a touch: only then can a
 *     crossing lie before it; an exact multiple root stays where it is).
 *     "Certainly": compensated Horner beyond twice its error bound
 *     (u |v| + gamma_{2n}^2 sum |c_i| x^i), with the leading terms step 3
 *     dropped added back by plain Horner (beyond twice their bound): for
 *     the coefficients as given.  So is almost every root (kappa below
 *     about 1 / (n^2 u)): one evaluation.  Else r lies in the rounding band
 *     of a cluster (the polish may settle on a later root of it, or a touch
 *     be found after a crossing inside the band), and the answer is the
 *     earliest point that cannot be excluded: steps left from r, doubling,
 *     until p is certainly positive, then bisection between that point and
 *     the last that was not, until they are r 2^-50 apart; reported as a
 *     crossing where p is certainly negative there, else as a touch
 *     (*graze = 1).  Checked against the exact first root of the
 *     coefficients as given (tests/runtime/test_hostile_fuzz.py: never
 *     later by more than 8 ulps).  At the extreme spreads of step 4 it is
 *     applied to the slice's scaled polynomial, and to the closed forms of
 *     degree 1 and 2 where step 3 dropped leading terms (their root is
 *     that of the rest: up to 7e-8 relative late near a double root).  Not
 *     applied beyond 2^60 (compensated Horner is unscaled), nor to degrees
 *     1 and 2 as given (their closed forms are exact to rounding).
 *     Degree 1 and 2 use closed forms; the quadratic uses an FMA-corrected
 *     discriminant (Kahan) and the cancellation-free formula; its graze
 *     check is the same bound at the vertex.  An exactly zero discriminant
 *     is always reported as a graze.
 *   M2C_METHOD_INTERVAL_NOGRAZE  the same without the graze check (q = p;
 *     benchmark baseline: misses double roots, as plain interval solvers do).
 *   Contact skin (m2c_first_root_skin, m2c_first_roots): an optional eps >= 0
 *     in the units of c (distance squared for the shipped equations, whose
 *     polynomial is |d(t)|^2 - R^2: a pass at gap g has a minimum of about
 *     2 R g) makes a critical point where |p| <= eps + the rounding bound,
 *     without a sign change, a touch: a near-miss within the skin is
 *     reported as contact at the time of closest approach.  Only a minimum
 *     of |p| is a touch: a maximum (p(0) within the skin, the bodies first
 *     moving apart) is the farthest pass, and the scan goes on.  Crossings are
 *     reported exactly as without it.  eps = 0 is the default behaviour.
 *     It applies to the interval method (the quadratic's vertex included) and
 *     to the polynomial left after exact factors of t are divided out (step
 *     2: then in the units of c / t^j).
 *   M2C_METHOD_GSL  what the original tool did: gsl_poly_complex_solve
 *     (companion matrix) with GSL's error handler switched off for the call
 *     (and restored), smallest root in (0, tmax] whose imaginary part is at
 *     most sqrt(DBL_EPSILON) times its modulus; such a root with nonzero
 *     imaginary part is reported as a graze.  Closed forms for degree <= 2.
 *   M2C_METHOD_CLOSED  closed forms: the quadratic above for degree <= 2; for
 *     degree 3 and 4 the quartic solver of Orellana & De Michele (ACM TOMS
 *     Algorithm 1010: LDL^T factoring into two quadratics, refined by
 *     Newton on the factor coefficients), a cubic being solved as the quartic
 *     t * p(t) whose extra root 0 lies outside (0, tmax].  Real roots are
 *     chosen as for GSL.  Degree > 4 falls back to M2C_METHOD_INTERVAL.
 */
#ifndef MAX2CODE_ROOTS_H
#define MAX2CODE_ROOTS_H

#ifdef __cplusplus
extern "C" {
#endif

#define M2C_MAX_DEGREE 16

/* BEGIN methods: written from runtime/methods.toml by scripts/runtime-methods */
#define M2C_METHOD_INTERVAL 0  /* interval solver with the graze (double root) check: the default */
#define M2C_METHOD_INTERVAL_NOGRAZE 1  /* interval solver, sign changes only (no graze check) */
#define M2C_METHOD_GSL 2  /* GSL's companion-matrix solve, as the original tool did (C runtime built with GSL) */
#define M2C_METHOD_CLOSED 3  /* closed forms up to degree 4, the interval solver above or if a closed form overflows */
#define M2C_METHOD_COUNT 4  /* valid methods: 0 .. COUNT - 1 */
/* END methods */

/* Default method (interval solver with graze check). */
int m2c_first_root(const double c[], int degree, double tmax, double *t);

/* Any method; an unknown method number is invalid input (-1). */
int m2c_first_root_method(const double c[], int degree, double tmax, double *t,
                          int method);

/* Like m2c_first_root_method; also sets *graze (when 1 is returned) to 1 if
 * the reported root is a touch (double root without sign change), else 0.
 * graze may be NULL. */
int m2c_first_root_ex(const double c[], int degree, double tmax, double *t,
                      int method, int *graze);

/* The default method with a contact skin eps >= 0 (see "Contact skin"):
 * eps = 0 gives exactly m2c_first_root_ex(..., M2C_METHOD_INTERVAL, graze).
 * graze may be NULL. */
int m2c_first_root_skin(const double c[], int degree, double tmax, double eps,
                        double *t, int *graze);

/* Batch: m polynomials of one degree, row i at c + i (degree + 1), each
 * solved as m2c_first_root_skin(row, degree, tmax, eps, ...) would.  t[i] is
 * the root, or NaN when there is none or row i is invalid; status[i] (status
 * may be NULL) is that call's 1, 0 or -1.  Returns the number of roots found,
 * or -1 (nothing written) when c or t is NULL, m < 0 or degree is outside
 * 0..16. */
int m2c_first_roots(const double c[], int m, int degree, double tmax,
                    double eps, double t[], int status[]);

#ifdef __cplusplus
}
#endif

#endif /* MAX2CODE_ROOTS_H */
