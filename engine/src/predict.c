/*
 * predict.c -- when does a pair of bodies first touch?
 *
 * A pair is a set of features: a point (a vertex with the body's rounding radius) against a
 * point, and a point against an edge's line. Each feature's contact condition is one of the
 * generated equations, evaluated in the pair's relative frame (the second body's translation
 * subtracted, so equal gravity cancels exactly and the generated dispatch picks a cheaper
 * variant):
 *   point-point  circles_orbit*      |P - Q|^2 - R^2          (R = sum of the radii)
 *   point-edge   circle_orbit_line*  side (P - L) x D - R     (D the edge's unit direction)
 * Without rotation the polynomial is the exact motion and one solve gives the contact time.
 *
 * Which roots count: a contact begins where the gap function goes from positive to negative
 * (its derivative there < 0; a touching double root -- a graze -- is no contact, nor is one
 * that rounding split into two close roots: the gap dips no deeper than the tolerance), and
 * for an edge only where the point's projection lies on the edge. A root that does not count is
 * stepped over: the polynomial is re-expanded at that root with its constant term set to
 * exactly 0, and the runtime (which divides out a root at 0) finds the next one; a
 * polynomial of degree n has at most n roots, so the walk ends. Touching now (the gap within
 * the tolerance, as after a response): approaching (derivative below -v_eps) is a contact
 * now; otherwise the constant term is set to 0 and the next root is the next contact -- the
 * separating condition, so a pair that has just bounced is never hit again at t ~ 0.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "engine.h"
#include "max2code_roots.h"

#include "circles_orbit_o1.h"
#include "circles_orbit_o2.h"
#include "circles_orbit_o3.h"
#include "circles_orbit.h"
#include "circles_orbit_o6.h"
#include "circle_orbit_line_o1.h"
#include "circle_orbit_line_o2.h"
#include "circle_orbit_line_o3.h"
#include "circle_orbit_line.h"
#include "circle_orbit_line_o6.h"

#define MAXC 17 /* coefficients: degree <= 16 (the runtime's limit) */

typedef int (*coef_fn)(const double p[], double c[]);

/* The models, by slot: slot 0 is the exact, non-rotating motion (every order's no-orbit
 * variants are the same); the others are the Taylor orders of the rotation, lowest first.
 * Order 6 is degree 12; order 8 (degree 16, within the runtime's limit) missed a contact in
 * tests/engine/test_rotation.py when tried, and is left out until that is understood. */
#define NSLOTS 6
#define TOP_SLOT (NSLOTS - 1)
/* One model of a feature's gap: the generated coefficients, their degree and parameter names. */
typedef struct {
    coef_fn coef;
    int degree;
    const char *const *names;
} model;
#define MODEL(eq) {eq##_coefficients, eq##_DEGREE, eq##_param_names}

/* The predictors, one row per slot: the Taylor order of the rotation, and the model of each
 * feature kind (point-point, point-line) at that order. */
static const struct {
    int order;
    model pp, pl;
} SLOT[NSLOTS] = {
    {0, MODEL(circles_orbit_o1), MODEL(circle_orbit_line_o1)},
    {1, MODEL(circles_orbit_o1), MODEL(circle_orbit_line_o1)},
    {2, MODEL(circles_orbit_o2), MODEL(circle_orbit_line_o2)},
    {3, MODEL(circles_orbit_o3), MODEL(circle_orbit_line_o3)},
    {4, MODEL(circles_orbit), MODEL(circle_orbit_line)},
    {6, MODEL(circles_orbit_o6), MODEL(circle_orbit_line_o6)},
};
#undef MODEL

/* Parameter order of the equations (checked against the generated names at start-up). */
enum { CX1, CY1, VX1, VY1, AX1, AY1, OX1, OY1, W1, R1,
       CX2, CY2, VX2, VY2, AX2, AY2, OX2, OY2, W2, R2, PP_NPARAMS };
static const char *const PP_EXPECTED[PP_NPARAMS] = {
    "cx1", "cy1", "vx1", "vy1", "ax1", "ay1", "ox1", "oy1", "w1", "r1",
    "cx2", "cy2", "vx2", "vy2", "ax2", "ay2", "ox2", "oy2", "w2", "r2"};
enum { CPX, CPY, VPX, VPY, APX, APY, OPX, OPY, WP, RR,
       CLX, CLY, VLX, VLY, ALX, ALY, OLX, OLY, DX, DY, WL, PL_NPARAMS };
static const char *const PL_EXPECTED[PL_NPARAMS] = {
    "cpx", "cpy", "vpx", "vpy", "apx", "apy", "opx", "opy", "wp", "r",
    "clx", "cly", "vlx", "vly", "alx", "aly", "olx", "oly", "dx", "dy", "wl"};

int predict_check_generated(m2c_world *w)
{
    for (int o = 0; o < NSLOTS; o++) {
        for (int k = 0; k < PP_NPARAMS; k++)
            if (strcmp(SLOT[o].pp.names[k], PP_EXPECTED[k]) != 0)
                goto bad;
        for (int k = 0; k < PL_NPARAMS; k++)
            if (strcmp(SLOT[o].pl.names[k], PL_EXPECTED[k]) != 0)
                goto bad;
        if (SLOT[o].pp.degree >= MAXC || SLOT[o].pl.degree >= MAXC)
            goto bad;
    }
    return 0;
bad:
    strcpy(w->err, "the generated equations' parameters are not the engine's (rebuild the engine)");
    return -1;
}

/* ------------------------------------------------------------------------------------------ */
/* One feature                                                                                  */
/* ------------------------------------------------------------------------------------------ */

typedef struct {
    m2c_world *w;
    const body *A, *B;      /* A owns the point; B the other point (PP) or the edge (PL) */
    snap a, b;              /* both at now */
    int kind;               /* F_PP or F_PL (an F_LP is an F_PL with the bodies swapped) */
    int va, vb, side;       /* vertex of A; vertex (PP) or edge (PL) of B; side of the edge */
    double R;               /* radius sum */
    double pa[2], pb[2];    /* world-frame offsets at now: A's point; B's point or edge start */
    double dir[2], len;     /* PL: the edge's unit direction at now (times side), its length */
    int rot_a, rot_b;       /* does rotation move A's point / B's point or line? */
    int no_touch;           /* a two-sided edge's other side: touching now is no contact */
    int ghost;              /* the pair passes through (a veto, a sensor): touching or
                               overlapping now is no contact, only a new crossing is */
    int leaves;             /* a sensor's ghost: a crossing out (the gap rising through 0 on the
                               feature) is an event too -- how the pair may stop overlapping */
    double rx, ry;          /* A's reference point minus B's, at the snapshots' time */
    int oa, ob;             /* the pair's first and second body's parts (not swapped with A
                               and B): their first vertices' body-level indices (a contact
                               names body-level vertices and edges) */
    double solver_h;        /* a pair the contact solver holds: the time to its next tick
                               (touching now is its business while the gap stays within the
                               tolerance until then); else 0 */
    double shrink;          /* the overlap the pair may keep (feature_slop): its contact
                               surface lies that far in; 0: exact */
    double kept;            /* how deep the pair's shapes overlap now, where a body left the
                               contact solver (pair_overlap); else 0 */
} feat;

/* A pair in sustained contact (contact_solver.c): one side in the solver, the other in it
 * too or held (static, kinematic, asleep). Its touching contacts are solved at the ticks;
 * an event for them now would be a rounding-level burst at one instant. */
static double solver_window(const m2c_world *w, const body *A, const body *B)
{
    int sa = A->kind == M2C_DYNAMIC && A->state == SOLVING;
    int sb = B->kind == M2C_DYNAMIC && B->state == SOLVING;
    if (!sa && !sb)
        return 0.0;
    const body *O = sa ? B : A;
    if (O->kind == M2C_DYNAMIC && O->state != SOLVING && O->state != ASLEEP)
        return 0.0;
    double H = solver_next_tick(w) - w->now;
    return H > 0 && H < INFINITY ? H : 0.0;
}

/* Does the gap polynomial c (time from now) stay above -tolp on [0, H]? (A lower bound: the
 * constant term plus every negative term at its largest.) */
static int stays_within(const double c[], int n, double H, double tolp)
{
    double low = c[0], hk = 1.0;
    for (int k = 1; k <= n; k++) {
        hk *= H;
        if (c[k] < 0)
            low += c[k] * hk;
    }
    return low >= -tolp;
}

/* A's reference point minus B's at time t, from their own reference states: the difference of
 * the reference positions first (exact when they are close), then the small motions -- never
 * two positions rounded at their own magnitude (bodies far from the origin keep their digits) */
static void relative_position(const body *A, const body *B, double t, double *rx, double *ry)
{
    double sa = t - A->m.t, sb = t - B->m.t;
    *rx = (A->m.x - B->m.x) + (sa * (A->m.vx + 0.5 * A->m.ax * sa) - sb * (B->m.vx + 0.5 * B->m.ax * sb));
    *ry = (A->m.y - B->m.y) + (sa * (A->m.vy + 0.5 * A->m.ay * sa) - sb * (B->m.vy + 0.5 * B->m.ay * sb));
}

static double derivative(const double c[], int n, double t)
{
    double v = n * c[n];
    for (int k = n - 1; k >= 1; k--)
        v = v * t + k * c[k];
    return v;
}

/* c(t) -> c(t + r) */
static void taylor_shift(double c[], int n, double r)
{
    for (int k = 0; k < n; k++)
        for (int j = n - 1; j >= k; j--)
            c[j] += r * c[j + 1];
}

/* Both equations list the two bodies' motions alike: a point's centre, velocity,
 * acceleration, rotating offset and angular velocity (indices 0-8), then the second body's
 * (10-17, its angular velocity at w2): in the pair's relative frame, with an offset that does
 * not rotate folded into its centre (so that more parameters are exactly zero). */
_Static_assert((int)CX1 == (int)CPX && (int)OY1 == (int)OPY && (int)W1 == (int)WP
                   && (int)CX2 == (int)CLX && (int)OY2 == (int)OLY,
               "circles_orbit and circle_orbit_line list the motions alike");

static void fill_motion(const feat *f, double p[], int w2)
{
    p[CX1] = f->rx;
    p[CY1] = f->ry;
    p[VX1] = f->a.vx - f->b.vx;
    p[VY1] = f->a.vy - f->b.vy;
    p[AX1] = f->a.ax - f->b.ax;
    p[AY1] = f->a.ay - f->b.ay;
    if (f->rot_a) {
        p[OX1] = f->pa[0];
        p[OY1] = f->pa[1];
        p[W1] = f->a.w;
    } else {
        p[CX1] += f->pa[0];
        p[CY1] += f->pa[1];
        p[OX1] = p[OY1] = p[W1] = 0.0;
    }
    p[VX2] = p[VY2] = p[AX2] = p[AY2] = 0.0;
    if (f->rot_b) {
        p[CX2] = p[CY2] = 0.0;
        p[OX2] = f->pb[0];
        p[OY2] = f->pb[1];
        p[w2] = f->b.w;
    } else {
        p[CX2] = f->pb[0];
        p[CY2] = f->pb[1];
        p[OX2] = p[OY2] = p[w2] = 0.0;
    }
}

static void fill_pp(const feat *f, double p[PP_NPARAMS], double dr)
{
    fill_motion(f, p, W2);
    p[R1] = f->A->radius + dr - f->shrink;
    p[R2] = f->B->radius;
}

static void fill_pl(const feat *f, double p[PL_NPARAMS], double dr)
{
    fill_motion(f, p, WL);
    p[RR] = f->R + dr - f->shrink;
    p[DX] = f->dir[0];
    p[DY] = f->dir[1];
}

/* Does the contact at time now + tau lie on the edge (exact motion)? */
static int on_edge(const feat *f, double tau)
{
    if (f->kind != F_PL)
        return 1;
    const m2c_world *w = f->w;
    double t = w->now + tau;
    snap a = motion_at(&f->A->m, t), b = motion_at(&f->B->m, t);
    double P[2], L[2], D[2];
    world_point(&a, &w->verts[2 * (f->A->vert + f->va)], P);
    world_point(&b, &w->verts[2 * (f->B->vert + f->vb)], L);
    world_vector(&b, &w->edges[3 * (f->B->vert + f->vb)], D);
    double u = (P[0] - L[0]) * D[0] + (P[1] - L[1]) * D[1];
    double slack = w->cfg.tolerance;
    return u >= -slack && u <= f->len + slack;
}

static void count_solve(m2c_world *w, int degree)
{
    w->st.solves++;
    w->st.solves_by_degree[degree < 0 ? 0 : degree > 16 ? 16 : degree]++;
}

/* The first contact of the exact polynomial c (degree n, time from now) in (0, tmax]:
 * 1 and *tau, else 0. tolp: |c0| within it is touching; vthr: a derivative below -vthr
 * approaches. */
/* No root in (0, tmax] when c0 outweighs every other term there (the common case: most
 * neighbours cannot meet before the body leaves its cell). */
static int clearly_apart(const double c[], int n, double tmax, double tolp)
{
    if (!(c[0] > tolp))
        return 0;
    double sum = 0.0, tk = 1.0;
    for (int k = 1; k <= n; k++) {
        tk *= tmax;
        sum += fabs(c[k]) * tk;
    }
    return c[0] > sum * (1 + 1e-12);
}

/* Does the gap c (shifted to the moment in question) only dip into the tolerance band and come
 * out again? A body sliding past a vertex or along a line at exactly touching distance has a
 * double root there (a graze), which the rounding of the coefficients splits into two roots
 * some sqrt(eps) apart with a derivative of sqrt(eps) times the speed; taken as an impact, it
 * gave a tangential slide an impulse (and the rest rule then stopped it dead, issue 33). The
 * local quadratic's lowest value c0 - c1^2 / (4 c2), at tau = -c1 / (2 c2), stays within the
 * tolerance (the higher terms too): no contact, the pair never overlaps by more than it. */
static int shallow_dip(const double c[], int n, double tolp)
{
    if (n < 2 || !(c[1] < 0) || !(c[2] > 0))
        return 0;
    double tau = -c[1] / (2 * c[2]), rest = 0.0, tk = tau * tau;
    for (int k = 3; k <= n; k++) {
        tk *= tau;
        rest += fabs(c[k]) * tk;
    }
    return c[0] + c[1] * tau / 2 - rest >= -tolp;
}

/* The mirror of shallow_dip: a gap that only rises into the tolerance band from below and goes
 * down again (a sensor's partner grazing its boundary from inside) is no crossing out. */
static int shallow_peak(const double c[], int n, double tolp)
{
    double neg[MAXC] = {0};
    for (int k = 0; k <= n; k++)
        neg[k] = -c[k];
    return shallow_dip(neg, n, tolp);
}

static int first_contact(feat *f, double c[MAXC], int n, double tmax, double tolp, double vthr,
                         double *tau, double *rate)
{
    double t0 = 0.0;
    if (clearly_apart(c, n, tmax, tolp))
        return 0;
    if (f->leaves && c[0] < -tolp) { /* deep inside and staying so: no crossing either way */
        double neg[MAXC] = {0};
        for (int k = 0; k <= n; k++)
            neg[k] = -c[k];
        if (clearly_apart(neg, n, tmax, tolp))
            return 0;
    }
    if (f->solver_h > 0 && stays_within(c, n, fmin(f->solver_h, tmax), tolp))
        return 0; /* the solver's next tick comes first (solver_window) */
    if (c[0] <= tolp && f->ghost) {
        if (c[0] >= -tolp)
            c[0] = 0.0; /* touching: only later roots count; deeper: its crossings, below */
    } else if (c[0] <= tolp && c[0] >= -tolp && f->no_touch) {
        /* touching the line, belonging to the other side: only later roots count. Not deeper:
         * a disc whose centre lies within its radius of a rail's line beyond the rail's end
         * (-0.106 m from this side's face, which it is not over) belongs to no face yet, and
         * taking its gap for 0 lifted the whole curve by 0.106 m: thrown up over the line, it
         * came down through the rail and met it 0.06 s late, 0.1 m deep
         * (tests/engine/test_bin_fuzz.py). Its crossings decide, below: up over the line
         * beyond the end is none, down onto the face is the contact */
        c[0] = 0.0;
    } else if (c[0] <= tolp) {
        if (c[0] >= -tolp || f->kind == F_PP) {   /* touching (or overlapping: Bannerman) */
            if (n >= 1 && c[1] < -vthr && !shallow_dip(c, n, tolp) && on_edge(f, 0.0)) {
                *tau = 0.0;
                *rate = -c[1];
                return 1;
            }
            /* pressed together with no speed (gravity onto a support): a contact now too,
             * for the rest rule to decide -- else it would sink in */
            if (n >= 2 && c[1] <= vthr && c[2] < 0 && on_edge(f, 0.0)) {
                *tau = 0.0;
                *rate = 0.0;
                return 1;
            }
            c[0] = 0.0;    /* separating or sliding: the next root after now */
        }
    }
    for (int iter = 0; iter <= n + 1; iter++) {
        double r;
        int graze = 0;
        count_solve(f->w, n);
        if (m2c_first_root_ex(c, n, tmax - t0, &r, M2C_METHOD_INTERVAL, &graze) != 1)
            return 0;
        double tr = t0 + r;
        double d = derivative(c, n, r);
        taylor_shift(c, n, r);
        c[0] = 0.0;
        if (!graze && d < 0 && shallow_dip(c, n, tolp))
            graze = 1; /* a double root split by rounding: a graze all the same */
        /* a touch without crossing (a graze) is no collision, but it is a first contact for
         * m2c_world_first_contact */
        if ((graze ? f->w->any_kinds : d < 0) && on_edge(f, tr)) {
            *tau = tr;
            *rate = -d;
            return 1;
        }
        if (f->leaves && !graze && d > 0 && !shallow_peak(c, n, tolp) && on_edge(f, tr)) {
            *tau = tr;
            *rate = -d; /* negative: a crossing out */
            return 1;
        }
        if (graze)
            c[1] = 0.0;
        t0 = tr;
        if (!(t0 < tmax))
            return 0;
    }
    return 0;
}

/* ------------------------------------------------------------------------------------------ */
/* Rotation: Taylor models in windows, proved by inflated and deflated models                  */
/* ------------------------------------------------------------------------------------------ */

#define MAX_WINDOWS 16       /* windows per feature and prediction; then the body re-predicts */
static const double FACT[10] = {1, 1, 2, 6, 24, 120, 720, 5040, 40320, 362880};

/* The feature's bodies, offsets and edge direction at absolute time t (exact motion). */
static void feat_at(feat *f, double t)
{
    const m2c_world *w = f->w;
    f->a = motion_at(&f->A->m, t);
    f->b = motion_at(&f->B->m, t);
    relative_position(f->A, f->B, t, &f->rx, &f->ry);
    world_vector(&f->a, &w->verts[2 * (f->A->vert + f->va)], f->pa);
    world_vector(&f->b, &w->verts[2 * (f->B->vert + f->vb)], f->pb);
    if (f->kind == F_PL) {
        double D[2];
        world_vector(&f->b, &w->edges[3 * (f->B->vert + f->vb)], D);
        f->dir[0] = f->side * D[0];
        f->dir[1] = f->side * D[1];
    }
}

/* The exact gap function at absolute time t: |P - Q|^2 - R^2, or side (P - L) x D - R. */
static double exact_gap(const feat *f, double t)
{
    const m2c_world *w = f->w;
    snap a = motion_at(&f->A->m, t), b = motion_at(&f->B->m, t);
    double P[2], Q[2];
    world_point(&a, &w->verts[2 * (f->A->vert + f->va)], P);
    world_point(&b, &w->verts[2 * (f->B->vert + f->vb)], Q);
    double dx = P[0] - Q[0], dy = P[1] - Q[1], R = f->R - f->shrink;
    if (f->kind == F_PP)
        return dx * dx + dy * dy - R * R;
    double D[2];
    world_vector(&b, &w->edges[3 * (f->B->vert + f->vb)], D);
    return f->side * (dx * D[1] - dy * D[0]) - R;
}

/* A crossing of the exact gap in [lo, hi] (absolute times), down (sense 1: g(lo) >= 0 >= g(hi))
 * or up (sense -1: the same for -g), by the Illinois method: to the last bit. */
static double refine_sense(const feat *f, double lo, double hi, double sense)
{
    double glo = sense * exact_gap(f, lo), ghi = sense * exact_gap(f, hi);
    if (!(glo > 0))
        return lo;
    if (!(ghi < 0))
        return hi;
    int side = 0;
    for (int it = 0; it < 100 && hi - lo > 2 * DBL_EPSILON * fabs(hi); it++) {
        double m = (lo * ghi - hi * glo) / (ghi - glo);
        if (!(m > lo && m < hi))
            m = 0.5 * (lo + hi);
        double gm = sense * exact_gap(f, m);
        if (gm > 0) {
            lo = m;
            glo = gm;
            if (side == 1)
                ghi *= 0.5;
            side = 1;
        } else {
            hi = m;
            ghi = gm;
            if (side == -1)
                glo *= 0.5;
            side = -1;
        }
    }
    return hi;
}

static double refine(const feat *f, double lo, double hi)
{
    return refine_sense(f, lo, hi, 1.0);
}

/* The crossing refined in [lo, hi] (absolute times): 1 and *tau (from now) when its contact
 * point lies on the edge; else 0 with *t0 moved to it -- the point went into the band beyond an
 * end, and the search goes on for later roots. */
static int take_crossing(const feat *f, double lo, double hi, double *t0, double *tau)
{
    double tc = refine(f, lo, hi);
    if (on_edge(f, tc - f->w->now)) {
        *tau = tc - f->w->now;
        return 1;
    }
    *t0 = tc - f->w->now;
    return 0;
}

/* Position error bound factor of the order-n model: |exact - model| <= sum rho |w|^(n+1) t^(n+1) /
 * (n+1)! for the rotating offsets (and the unit direction of a rotating edge). */
static double rot_term(const feat *f, int n)
{
    double s = 0.0;
    double ra = hypot(f->pa[0], f->pa[1]), rb = hypot(f->pb[0], f->pb[1]);
    if (f->rot_a)
        s += ra * pow(fabs(f->a.w), n + 1);
    if (f->rot_b)
        s += rb * pow(fabs(f->b.w), n + 1);
    return s / FACT[n + 1];
}

/* First root of the model c (degree n) in (0, h] at which it crosses in direction dir (-1 down,
 * +1 up); 1 and *t, else 0. */
static int crossing(m2c_world *w, const double c_in[MAXC], int n, double h, int dir, double *t)
{
    double c[MAXC];
    memcpy(c, c_in, sizeof c);
    double t0 = 0.0;
    for (int iter = 0; iter <= n + 1; iter++) {
        double r;
        int graze = 0;
        count_solve(w, n);
        if (m2c_first_root_ex(c, n, h - t0, &r, M2C_METHOD_INTERVAL, &graze) != 1)
            return 0;
        double d = derivative(c, n, r);
        if (graze || dir * d > 0) {
            *t = t0 + r;
            return 1;
        }
        taylor_shift(c, n, r);
        c[0] = 0.0;
        if (graze)
            c[1] = 0.0;
        t0 += r;
        if (!(t0 < h))
            return 0;
    }
    return 0;
}

/* When could the rotating feature touch at the earliest? Its rotating points stay within
 * their offsets' circles about the bodies' (polynomially moving) reference points, so the
 * exact, non-rotating contact of those circles (or of the circle and a non-rotating edge) comes
 * first: 1 and *t (0 when they overlap now), or 0 when even they never meet before tmax. */
static int bound_start(feat *f, double tmax, double tolp, double *t)
{
    feat g = *f;
    double p[PL_NPARAMS + 1], c[MAXC] = {0};
    int n;
    double ra = f->rot_a ? hypot(f->pa[0], f->pa[1]) : 0.0;
    g.rot_a = 0;
    g.pa[0] = f->rot_a ? 0.0 : f->pa[0];
    g.pa[1] = f->rot_a ? 0.0 : f->pa[1];
    if (f->kind == F_PL && !f->rot_b) {
        g.R = f->R + ra;
        fill_pl(&g, p, 0.0);
        n = SLOT[0].pl.coef(p, c);
    } else {
        double rb = f->rot_b ? (f->kind == F_PP ? hypot(f->pb[0], f->pb[1]) : f->B->rho) : 0.0;
        g.rot_b = 0;
        if (f->rot_b || f->kind == F_PL) {
            g.pb[0] = g.pb[1] = 0.0;
        }
        double extra = ra + rb + (f->kind == F_PL ? f->B->radius : 0.0);
        const body *A = f->A, *B = f->B;
        double r1 = f->kind == F_PP ? A->radius : f->R - B->radius;
        double r2 = f->kind == F_PP ? B->radius : B->radius;
        fill_pp(&g, p, 0.0);
        p[R1] = r1 + extra;
        p[R2] = r2;
        n = SLOT[0].pp.coef(p, c);
    }
    if (c[0] <= tolp) {
        /* overlapping, or touching within the tolerance: from now (a corner standing on a
         * floor touches it with the lowest point of its bounding circle, whose gap rounds to
         * either sign: a start a hair after now made the touching rules below miss it) */
        *t = 0.0;
        return 1;
    }
    double r;
    int graze = 0;
    count_solve(f->w, n);
    if (m2c_first_root_ex(c, n, tmax, &r, M2C_METHOD_INTERVAL, &graze) != 1)
        return 0;
    *t = r;
    return 1;
}

/* Does the gap curve down now (its second Taylor coefficient negative)?  From the window's model
 * c when its order is 2 or more -- its coefficients up to t^2 are then the exact motion's --
 * else from the order-2 model of the same state (feat_at's). */
static int pressed_in(const feat *f, int slot, const double c[MAXC])
{
    if (SLOT[slot].order >= 2)
        return c[2] < 0;
    double p[PL_NPARAMS + 1], c2[MAXC] = {0};
    if (f->kind == F_PP) {
        fill_pp(f, p, 0.0);
        SLOT[2].pp.coef(p, c2);
    } else {
        fill_pl(f, p, 0.0);
        SLOT[2].pl.coef(p, c2);
    }
    return c2[2] < 0;
}

/* A sensor's ghost, inside: the exact gap g at t (absolute, where the deflated model came up)
 * is within the band. Its crossing out lies between t and the inflated model's own up-crossing
 * (the exact gap is above that model); refined there, it counts when on the feature: 1 and
 * *tau (from now). */
static int crossing_out(const feat *f, const double ca[MAXC], int deg, double h, double t_win,
                        double t, double g, double *tau)
{
    m2c_world *w = f->w;
    double tc = t, ta;
    if (g < 0 && crossing(w, ca, deg, h, +1, &ta) && t_win + ta >= t)
        tc = refine_sense(f, t, t_win + ta, -1.0);
    if (!on_edge(f, tc - w->now))
        return 0;
    *tau = tc - w->now;
    return 1;
}

/* The rotating feature's first contact in (0, tmax] from now: 1 and *tau; 0 for none; 2 when
 * the search stopped at *tau (MAX_WINDOWS): the body must be predicted again by then. */
static int solve_rotating(feat *f, double tmax, double tolp, double vthr, double *tau, double *rate)
{
    m2c_world *w = f->w;
    double tol = w->cfg.tolerance;
    double t0 = 0.0, t_safe = -1.0;
    if (!bound_start(f, tmax, tolp, &t0))
        return 0;
    enum { ABOVE, INSIDE } mode = ABOVE;
    int after_root = 0, min_slot = 1;
    for (int win = 0; win < MAX_WINDOWS; win++) {
        if (!(t0 < tmax))
            return 0;
        double tabs = w->now + t0;
        feat_at(f, tabs);
        double H = tmax - t0;
        /* distance-like gap now, for the budget of the model error and the reach test */
        double dx = f->rx + f->pa[0] - f->pb[0], dy = f->ry + f->pa[1] - f->pb[1];
        double dist = f->kind == F_PP ? hypot(dx, dy) - (f->R - f->shrink)
                                      : dx * f->dir[1] - dy * f->dir[0] - (f->R - f->shrink);
        double dv = hypot(f->a.vx - f->b.vx, f->a.vy - f->b.vy);
        double da = hypot(f->a.ax - f->b.ax, f->a.ay - f->b.ay);
        double ra = hypot(f->pa[0], f->pa[1]), span = hypot(dx, dy) + f->R;
        /* how fast rotation can change the gap: the point's own turn, and the second body's
         * turn of its offset (point-point) or of the edge's line, whose distance from the point
         * changes at |w_b| times the point's distance from B's reference point, at most
         * |P - L| + |L - ref| <= span + |pb| (span + ra here, the first body's offset, let a
         * disc meet a fast-turning polygon's far edge unseen: the reach test skipped the
         * window) */
        double rb = hypot(f->pb[0], f->pb[1]);
        double spin = fabs(f->a.w) * ra + fabs(f->b.w) * (f->kind == F_PP ? rb : span + rb);
        double eps = fmax(tol, 0.25 * fabs(dist));
        /* the lowest order whose remainder over the rest of the horizon meets eps; else the
         * highest over the longest window that does */
        int slot = 0;
        /* at most a radian of rotation per window: beyond it the series' terms grow and cancel,
         * and rounding, which no remainder bound covers, would take over */
        double wmax = fmax(fabs(f->a.w), fabs(f->b.w));
        double h = fmin(H, 1.0 / wmax);
        H = h;
        for (int k = min_slot; k <= TOP_SLOT; k++)
            if (rot_term(f, SLOT[k].order) * pow(H, SLOT[k].order + 1) <= eps) {
                slot = k;
                break;
            }
        if (!slot) {
            slot = TOP_SLOT;
            h = pow(eps / rot_term(f, SLOT[slot].order), 1.0 / (SLOT[slot].order + 1));
            if (!(h < H))
                h = H;
        }
        int order = SLOT[slot].order;
        /* reach test: can the gap close within the window at all? */
        double reach = dv * h + 0.5 * da * h * h + spin * h;
        if (!after_root && (mode == ABOVE ? dist : -dist) - reach > 0) {
            t0 += h; /* cannot close (or, inside, open) the gap within the window */
            continue;
        }
        w->st.windows_solved++;
        double p[PL_NPARAMS + 1], c[MAXC] = {0};
        int n = f->kind == F_PP ? (fill_pp(f, p, 0.0), SLOT[slot].pp.coef(p, c))
                                : (fill_pl(f, p, 0.0), SLOT[slot].pl.coef(p, c));
        /* the model's error bound B(t) = kappa t^(n+1) on the gap function */
        double e_h = rot_term(f, order) * pow(h, order + 1);
        double kappa;
        if (f->kind == F_PP) {
            double reachmax = span + dv * h + 0.5 * da * h * h + 2 * ra + 2 * hypot(f->pb[0], f->pb[1]);
            kappa = rot_term(f, order) * (2 * reachmax * exp(fabs(f->a.w) * h + fabs(f->b.w) * h) + e_h);
        } else {
            double qmax = span + dv * h + 0.5 * da * h * h + 2 * ra + 2 * hypot(f->pb[0], f->pb[1]);
            double eD = f->rot_b ? pow(fabs(f->b.w), order + 1) / FACT[order + 1] : 0.0;
            kappa = rot_term(f, order) * exp(fabs(f->b.w) * h) + qmax * eD + rot_term(f, order) * eD * pow(h, order + 1);
        }
        int deg = n > order + 1 ? n : order + 1;
        double ca[MAXC], cb[MAXC];
        memcpy(ca, c, sizeof ca);
        memcpy(cb, c, sizeof cb);
        ca[order + 1] -= kappa;
        cb[order + 1] += kappa;
        double g0 = c[0], g1 = c[1];
        /* touching counts only where the prediction starts (after a response); later, a
         * re-expansion that finds the gap closed has passed the crossing: it lies after the
         * last point known to be apart, and is refined there on the exact motion */
        int at_start = t0 == 0.0;
        if (at_start && f->solver_h > 0 && f->solver_h <= h
            && stays_within(ca, deg, f->solver_h, tolp))
            return 0; /* the solver's next tick comes first (solver_window) */
        if (!after_root && !at_start && mode == ABOVE && g0 <= 0 && t_safe >= 0) {
            if (take_crossing(f, w->now + t_safe, tabs, &t0, tau)) {
                *rate = -g1;
                return 1;
            }
            mode = INSIDE;
            after_root = 1;
            continue;
        }
        /* a re-expansion from above that lands a hair past the crossing (within the
         * tolerance: the model after a root had its constant set to 0) with no point known
         * apart to refine from is touching now, and the touching rules below decide */
        int touching = mode == ABOVE && t_safe < 0 && g0 <= 0 && g0 >= -tolp;
        if (!after_root && !at_start && !touching) {
            mode = g0 > 0 ? ABOVE : INSIDE;
        } else if (!after_root && fabs(g0) <= tolp && (f->no_touch || f->ghost)) {
            /* a point touching the other side's face belongs there (no_touch): a speed to this
             * side within the rounding (vthr) does not bring it over.  Taken as above this
             * face, a spinning box's corner that had just bounced off the other face (e = 0:
             * +2.2e-16 m/s, its path curving back at 24.8 m/s^2) crossed this face at once,
             * and that false contact recurred at one instant until `stuck`
             * (tests/engine/test_stuck.py) */
            mode = g1 < 0 || (f->no_touch && !f->ghost && g1 <= vthr) ? INSIDE : ABOVE;
            after_root = 1;
        } else if (!after_root && fabs(g0) <= tolp) {
            if (g1 < -vthr) { /* touching and approaching: a contact now, if on the edge */
                if (on_edge(f, t0)) {
                    *tau = t0;
                    *rate = -g1;
                    return 1;
                }
                mode = INSIDE;
            } else if (g1 <= vthr && pressed_in(f, slot, c) && on_edge(f, t0)) {
                /* pressed together with no speed, the gap curving down (first_contact's rule):
                 * a contact now, for the rest rule to decide.  Without it the root at 0 was
                 * divided out, the rest of the model lay below zero from the start, no crossing
                 * was found, and a corner that a burst of bounces had brought to rest on a
                 * floor sank through it (a spinning box, tests/engine/test_rotation.py) */
                *tau = t0;
                *rate = 0.0;
                return 1;
            } else {
                mode = ABOVE;
            }
            after_root = 1;
        } else if (!after_root) {
            mode = g0 > 0 ? ABOVE : INSIDE;
        }
        if (after_root)
            ca[0] = cb[0] = 0.0;
        else if (g0 > 0)
            t_safe = t0;
        int root_here = after_root;
        after_root = 0;
        double ta, tb;
        if (mode == INSIDE) {
            /* below zero until the deflated model comes up: skip to there */
            if (!crossing(w, cb, deg, h, +1, &ta)) {
                t0 += h;
                continue;
            }
            double t_win = t0;
            t0 += ta;
            /* the deflated model bounds the gap from above: its up-crossing is the earliest the
             * exact gap can come up, and it may still be below zero there.  Only a gap within
             * the tolerance is a root (the next window sets its model's constant to 0); a gap
             * still deeper stays inside, re-expanded from here.  (Calling any gap <= tolp a
             * root shifted the next model up by that depth -- 2.5e-7 for a capsule spinning at
             * 5067 rad/s -- its down-crossing came after the exact one, the re-expansion there
             * found the gap closed with no point known apart, and the contact was lost:
             * tests/engine/test_no_tunnelling_fuzz.py, the spinning capsule.) */
            double g = exact_gap(f, w->now + t0);
            if (g < -tolp)
                continue;
            if (f->leaves && crossing_out(f, ca, deg, h, w->now + t_win, w->now + t0, g, tau)) {
                *rate = -(dv + spin + DBL_MIN); /* negative: a crossing out */
                return 1;
            }
            mode = ABOVE;
            after_root = g <= tolp;
            continue;
        }
        if (!crossing(w, ca, deg, h, -1, &ta)) { /* even the inflated model stays apart */
            t0 += h;
            continue;
        }
        int have_b = crossing(w, cb, deg, h, -1, &tb);
        double vrel = dv + da * h + spin + DBL_MIN;
        if (have_b && tb >= ta && ((tb - ta) * vrel <= tol || tb - ta <= 4 * DBL_EPSILON * (tabs + tb))) {
            if (take_crossing(f, tabs + ta, tabs + tb, &t0, tau)) {
                *rate = vrel;
                return 1;
            }
            mode = INSIDE;
            after_root = 1;
            continue;
        }
        /* no contact before t0 + ta: re-expand from the exact state there.  A step that does
         * not move absolute time re-expands from the same state and repeats for ever: a pair
         * touching with no approaching speed (a static rail's end on a slowly turning held
         * box's edge, gap -4e-17 m) had its order-1 model's error term kappa t^2 swamp the
         * gap's zero slope, so each window's inflated model crossed after 2.8e-17 s and the
         * same instant recurred until `stuck`.  A higher order carries the gap's curvature in
         * the model itself and leaves a remainder of a higher power: redo the window with it.
         * So too for a step a millionth of the window or less, which moves time by an ulp or
         * two: a triangle's corner held on a bin's wall (slope 5e-18 m/s, kappa 1.1e-3) stepped
         * 4.8e-15 s a window, 7.6e-14 s a prediction, until `stuck` (tests/engine/test_stuck.py,
         * drawn worlds in a bin) */
        if (slot < TOP_SLOT && ta > 0 && (w->now + (t0 + ta) == tabs || ta <= 1e-6 * h)) {
            min_slot = slot + 1;
            after_root = root_here;
            continue;
        }
        if (!(ta > 0))
            ta = fmax(h * 1e-3, 4 * DBL_EPSILON * (tabs + 1));
        t0 += ta;
    }
    *tau = t0;
    return 2;
}

/* The overlap the feature's pair may keep: the contact solver's slop (solver_slop) for a pair
 * it holds -- its PGS solve meets the contacts of a jammed pile only to about 1e-7 m/s, and at
 * the exact events' tolerance each miss was an event at the tick, local solves between the
 * wedged neighbours, and the wedge rule stopping the whole pile once per tick (issue 34) -- and
 * for a pair that overlaps now beyond the tolerance (one the solver held, set flying by an
 * edit: with its surface at 0 an overlapping point pressed further in crossed no root, and
 * sank). Within it a pair is no event; beyond it, an exact one. 0 elsewhere: exact. */
static double feature_slop(feat *f, double tolp)
{
    double S = solver_slop(f->w);
    if (!(S > 0) || f->ghost)
        return 0.0; /* (a sensor's or vetoed pair overlaps by design: its crossings are exact) */
    if (f->kind == F_PP)
        S = fmin(S, 0.5 * f->R);
    if (f->solver_h > 0)
        return S;
    f->shrink = 0.0;
    /* elsewhere only as deep as the overlap is now: pressing further in is an event at once
     * (a slop for every pair let thrown compounds in zero gravity sink 1e-5 m into walls, and
     * a box the solver had held, flying at 98 m/s long after, meet a ball 1e-5 m deep).
     * Whatever made the overlap: only a body that had left the solver and met nothing since
     * kept it before, and a disc the solver held 1e-5 m into a spinning pentagon, struck off
     * it at a tick by an exact impact, counted as exact, started inside the pentagon, looked
     * only for the way out and sank 3 mm in 9 ms, 12 cm by the next ticks, whose push-out
     * threw it at 15 m/s (+400 J; tests/engine/test_stuck.py, drawn worlds in a bin) */
    /* and only where the shapes overlap now, at most as deep as they do: a feature's gap is
     * negative wherever the point lies behind the edge's line, anywhere along it, however far
     * apart the shapes are (a rhombus that had left the solver, 0.03 m from a capsule spinning
     * at 1365 rad/s, kept 1e-5 m against the capsule's far side; when the turn brought that
     * side round, the contact came 1e-5 m deep: issue 33, the fuzz's tunnelling world) */
    double tol = f->w->cfg.tolerance;
    if (!(f->kept > tol))
        return 0.0;
    /* the shrink is a length (taken off the radii): how deep the feature is in now, plus the
     * tolerance, so that pressing further in is an event. A point pair's gap is d^2 - R^2, not
     * a length: taking its 3e-6 m^2 for a disc 1e-5 m into a triangle's apex as the shrink left
     * the pair 7e-6 m past touching already, so no crossing lay ahead, and the disc, flying
     * again, sank 4 cm into the apex with no event (the solver's push-out then threw it at
     * 6 m/s: a drawn world in a bin, tests/engine/test_stuck.py's kind) */
    double g0 = exact_gap(f, f->w->now);
    double depth = f->kind == F_PP ? f->R - sqrt(fmax(f->R * f->R + g0, 0.0)) : -g0;
    return g0 < -tolp ? fmin(fmin(S, tol + depth), f->kept + tol) : 0.0;
}

static int solve_feature(feat *f, double tmax, double *tau, double *rate)
{
    double c[MAXC] = {0};
    double p[PL_NPARAMS + 1];
    int n;
    /* a speed below vthr is no approach (rounding); a 1-norm bound of the relative speed */
    double dv = fabs(f->a.vx - f->b.vx) + fabs(f->a.vy - f->b.vy)
                + fabs(f->a.w) * (fabs(f->pa[0]) + fabs(f->pa[1]))
                + fabs(f->b.w) * (fabs(f->pb[0]) + fabs(f->pb[1]));
    double vthr = 1e-12 * dv + DBL_MIN;
    double tol = f->w->cfg.tolerance, tolp;
    f->shrink = feature_slop(f, f->kind == F_PP ? tol * (2 * f->R + tol) : tol);
    if (f->shrink > 0 && f->kind == F_PL && f->solver_h > 0
        && (fabs(f->a.w) + fabs(f->b.w)) * f->solver_h <= 0.5 * SOLVER_CONE_SLACK) {
        /* with an overlap kept, a corner sunk into a face lies on the next face's line too (a
         * box on an aligned box: its corner on the lower one's side, sideways events,
         * ping-pong, wedge stops): a vertex meets an edge only along a normal in its own
         * normal cone, as the solver's contacts (the deepest overlap of two convex shapes is
         * always such a pair: the overlap stays within the slop). Only while the cone turns
         * by less than half its slack before the next tick: a spinning box's cone now says
         * nothing about its corner later (spinning boxes overlapped by 0.014 m) */
        double d[2] = {-f->dir[1], f->dir[0]};
        if (!solver_in_cone(f->w, f->A, &f->a, f->va, d))
            return 0;
    }
    if (f->rot_a || f->rot_b) {
        double norm = f->kind == F_PP ? 2 * f->R : 1.0;
        tolp = f->kind == F_PP ? tol * (2 * f->R + tol) : tol;
        int r = solve_rotating(f, tmax, tolp, vthr * norm, tau, rate);
        feat_at(f, f->w->now); /* the caller's loops go on from now */
        if (r == 1)
            *rate /= norm;
        return r;
    }
    double norm = 1.0;
    if (f->kind == F_PP) {
        fill_pp(f, p, 0.0);
        n = SLOT[0].pp.coef(p, c);
        tolp = tol * (2 * f->R + tol);
        norm = 2 * f->R;
        vthr *= norm;
    } else {
        fill_pl(f, p, 0.0);
        n = SLOT[0].pl.coef(p, c);
        tolp = tol;
    }
    if (!first_contact(f, c, n, tmax, tolp, vthr, tau, rate))
        return 0;
    *rate /= norm; /* a speed, for both kinds */
    return 1;
}

/* ------------------------------------------------------------------------------------------ */
/* A pair                                                                                       */
/* ------------------------------------------------------------------------------------------ */

static int nedges(const body *b)
{
    return b->nvert >= 3 ? b->nvert : b->nvert - 1;
}

static void set_point(const m2c_world *w, const body *B, const snap *s, int v, double out[2])
{
    world_vector(s, &w->verts[2 * (B->vert + v)], out);
}

static void try_feature(feat *f, contact *best, int swapped, int fa, int fb)
{
    const m2c_world *w = f->w;
    double tmax = best->t - w->now, tau, rate = 0.0;
    if (!(tmax >= 0))
        return;
    int r = solve_feature(f, tmax > 0 ? tmax : 0x1p-1074, &tau, &rate);
    if (r == 2) { /* searched up to now + tau only: predict again by then */
        if (w->now + tau < best->window)
            best->window = w->now + tau;
        return;
    }
    if (r == 1
        && (w->now + tau < best->t || (w->now + tau == best->t && rate > best->rate))) {
        best->t = w->now + tau;
        best->rate = rate;
        best->improved = 1;
        best->feature = f->kind == F_PP ? F_PP : swapped ? F_LP : F_PL;
        best->fa = fa + f->oa;
        best->fb = fb + f->ob;
        best->side = f->side;
        best->up = rate < 0;
    }
}

/* Point features of A (vertices) against the edges of B. */
static void points_on_edges(feat *f, contact *best, int swapped)
{
    const m2c_world *w = f->w;
    const body *A = f->A, *B = f->B;
    int ne = nedges(B);
    if (ne <= 0)
        return;
    int closed = B->nvert >= 3;
    f->kind = F_PL;
    f->R = A->radius + B->radius;
    f->rot_b = f->b.w != 0.0;
    for (int eb = 0; eb < ne; eb++) {
        const double *e = &w->edges[3 * (B->vert + eb)];
        double D[2];
        world_vector(&f->b, e, D);
        set_point(w, B, &f->b, eb, f->pb);
        f->vb = eb;
        f->len = e[2];
        for (int va = 0; va < A->nvert; va++) {
            set_point(w, A, &f->a, va, f->pa);
            f->va = va;
            f->rot_a = f->a.w != 0.0 && (f->pa[0] != 0.0 || f->pa[1] != 0.0);
            /* a two-sided edge: a point on its line belongs to the side it is moving to (it has
             * just bounced off that side); touching the other side now is no contact */
            int own = 0;
            if (!closed) {
                double q[2] = {f->rx + f->pa[0] - f->pb[0], f->ry + f->pa[1] - f->pb[1]};
                double across = q[0] * D[1] - q[1] * D[0];
                if (fabs(across) <= w->cfg.tolerance + f->R) {
                    double vq[2] = {f->a.vx - f->a.w * f->pa[1] - (f->b.vx - f->b.w * f->pb[1]),
                                    f->a.vy + f->a.w * f->pa[0] - (f->b.vy + f->b.w * f->pb[0])};
                    double rate = vq[0] * D[1] - vq[1] * D[0] + f->b.w * (q[0] * D[0] + q[1] * D[1]);
                    double where = fabs(across) > w->cfg.tolerance ? across : rate;
                    if (fabs(across) <= w->cfg.tolerance && f->A->nvert >= 3) {
                        /* a polygon's corner on the line: the polygon is on the side of its
                         * interior next to that corner (its speed says nothing when it was
                         * resting there and turns into the edge: it would pass through) */
                        int nv = f->A->nvert;
                        double pp[2], pn[2];
                        set_point(w, f->A, &f->a, (va + nv - 1) % nv, pp);
                        set_point(w, f->A, &f->a, (va + 1) % nv, pn);
                        double ix = pp[0] + pn[0] - 2 * f->pa[0], iy = pp[1] + pn[1] - 2 * f->pa[1];
                        double inner = ix * D[1] - iy * D[0];
                        if (inner != 0.0)
                            where = inner;
                    }
                    own = where > 0 ? 1 : where < 0 ? -1 : 2;
                }
            }
            for (int side = 1; side >= (closed ? 1 : -1); side -= 2) {
                f->side = side;
                f->no_touch = own != 0 && own != side;
                f->dir[0] = side * D[0];
                f->dir[1] = side * D[1];
                if (swapped)
                    try_feature(f, best, 1, eb, va);
                else
                    try_feature(f, best, 0, va, eb);
            }
        }
    }
}

/* The second derivative now of the gap (a distance) of the event's feature between bodies i
 * and j, from the order-2 model of the generated equations: the bodies' relative acceleration
 * along the normal plus what rotation adds (a spinning corner curves into its partner, the
 * centripetal and Coriolis terms). Two responses need it: a pair pressed together with no
 * approach speed (solve_rotating reports such a contact now, pressed_in: unless the response
 * parts the pair, the same contact is found again at the same instant, forever), and a soft
 * contact of the contact solver, which parts at -accel h / 2 (contact_solver.c) for the
 * same reason. One helper for both: they computed it twice, by hand and from the model. */
double contact_gap_accel(m2c_world *w, int i, int j, const event *ev, int *rotates)
{
    int swapped = ev->feature == F_LP;
    feat f;
    memset(&f, 0, sizeof f);
    f.w = w;
    /* the features' parts as bodies, the indices theirs */
    const body *A = &w->b[swapped ? j : i], *B = &w->b[swapped ? i : j];
    int va = swapped ? ev->fb : ev->fa, vb = swapped ? ev->fa : ev->fb;
    body pa = part_view(w, A, vertex_part(w, A, va)), pb = part_view(w, B, vertex_part(w, B, vb));
    f.A = &pa;
    f.B = &pb;
    f.a = motion_at(&f.A->m, w->now);
    f.b = motion_at(&f.B->m, w->now);
    relative_position(f.A, f.B, w->now, &f.rx, &f.ry);
    f.va = va - (pa.vert - A->vert);
    f.vb = vb - (pb.vert - B->vert);
    set_point(w, f.A, &f.a, f.va, f.pa);
    f.rot_a = f.a.w != 0.0 && (f.pa[0] != 0.0 || f.pa[1] != 0.0);
    f.R = f.A->radius + f.B->radius;
    set_point(w, f.B, &f.b, f.vb, f.pb);
    f.rot_b = ev->feature == F_PP ? f.b.w != 0.0 && (f.pb[0] != 0.0 || f.pb[1] != 0.0) : f.b.w != 0.0;
    if (rotates)
        *rotates = f.rot_a || f.rot_b;
    double p[PL_NPARAMS + 1], c[MAXC] = {0};
    if (ev->feature == F_PP) {
        /* the gap is |P - Q|^2 - R^2 = d^2 - R^2: c2 = d d'' + d'^2 with d = R, d' = c1 / 2R */
        f.kind = F_PP;
        fill_pp(&f, p, 0.0);
        SLOT[2].pp.coef(p, c);
        if (!(f.R > 0))
            return 0.0;
        double d1 = c[1] / (2 * f.R);
        return (c[2] - d1 * d1) / f.R;
    }
    f.kind = F_PL;
    f.side = ev->side;
    double D[2];
    world_vector(&f.b, &w->edges[3 * (f.B->vert + f.vb)], D);
    f.dir[0] = f.side * D[0];
    f.dir[1] = f.side * D[1];
    f.len = w->edges[3 * (f.B->vert + f.vb) + 2];
    fill_pl(&f, p, 0.0);
    SLOT[2].pl.coef(p, c);
    return 2 * c[2];
}

/* A part's bounding circle now: its centre (the mean of its vertices, turned to the world
 * frame, from the body's reference point) into c, its radius returned (rounding included). */
static double part_circle(const m2c_world *w, const body *P, const snap *s, double c[2])
{
    double m[2] = {0.0, 0.0}, r = 0.0;
    const double *v = &w->verts[2 * P->vert];
    for (int k = 0; k < P->nvert; k++) {
        m[0] += v[2 * k] / P->nvert;
        m[1] += v[2 * k + 1] / P->nvert;
    }
    for (int k = 0; k < P->nvert; k++)
        r = fmax(r, hypot(v[2 * k] - m[0], v[2 * k + 1] - m[1]));
    world_vector(s, m, c);
    return r * (1 + 1e-12) + P->radius;
}

/* The features of a pair of shapes (single-shape bodies, or one part of each: f->A, f->B). */
static void predict_parts(feat *f, contact *c)
{
    const m2c_world *w = f->w;
    /* points against points: only rounded shapes (sharp corners meet through the edges) */
    if (f->A->radius + f->B->radius > 0) {
        f->kind = F_PP;
        f->R = f->A->radius + f->B->radius;
        f->side = 1;
        for (int va = 0; va < f->A->nvert; va++) {
            set_point(w, f->A, &f->a, va, f->pa);
            f->va = va;
            f->rot_a = f->a.w != 0.0 && (f->pa[0] != 0.0 || f->pa[1] != 0.0);
            for (int vb = 0; vb < f->B->nvert; vb++) {
                set_point(w, f->B, &f->b, vb, f->pb);
                f->vb = vb;
                f->rot_b = f->b.w != 0.0 && (f->pb[0] != 0.0 || f->pb[1] != 0.0);
                try_feature(f, c, 0, va, vb);
            }
        }
    }
    if (f->B->nvert > 1)
        points_on_edges(f, c, 0);
    if (f->A->nvert > 1) {
        /* the edges of A against the points of B: the same equation with the roles swapped */
        feat g = *f;
        g.A = f->B;
        g.B = f->A;
        g.a = f->b;
        g.b = f->a;
        g.rx = -f->rx;
        g.ry = -f->ry;
        points_on_edges(&g, c, 1);
    }
}

/* How deep the shapes of bodies i and j overlap now (0 when apart), for feature_slop: outside
 * the solver's own pairs, and only when the bounding circles about the reference points meet. */
static double pair_overlap(m2c_world *w, int i, int j, const feat *f)
{
    const body *A = &w->b[i], *B = &w->b[j];
    if (f->solver_h > 0 || f->ghost || !(solver_slop(w) > 0))
        return 0.0;
    double reach = A->bound + B->bound;
    if (f->rx * f->rx + f->ry * f->ry > reach * reach * (1 + 1e-12))
        return 0.0;
    double g = shape_signed_gap(w, i, j, w->now); /* (out of memory: -INFINITY, kept whole) */
    return g < 0 ? -g : 0.0;
}

int predict_pair(m2c_world *w, int i, int j, contact *c)
{
    const body *A = &w->b[i], *B = &w->b[j];
    if (!pair_filtered(A, B) || A->kind == KIND_REMOVED || B->kind == KIND_REMOVED)
        return 0;
    if (A->kind != M2C_DYNAMIC && B->kind != M2C_DYNAMIC && !w->any_kinds)
        return 0;
    if (A->state == RESTING && A->support == j)
        return 0; /* in contact by construction (the rest rule) */
    w->st.pair_tests++;
    c->improved = 0;
    feat f;
    f.w = w;
    f.A = A;
    f.B = B;
    /* The two cheapest tests, before evaluating the motions (the velocities now are
     * motion_at's, bit for bit): */
    double sa = w->now - A->m.t, sb = w->now - B->m.t;
    double dvx = (A->m.vx + A->m.ax * sa) - (B->m.vx + B->m.ax * sb);
    double dvy = (A->m.vy + A->m.ay * sa) - (B->m.vy + B->m.ay * sb);
    /* the same translation and no turn (two bodies the wedge rule stopped at one instant, a
     * body at rest against a static one in zero gravity): every gap between them is constant
     * in time, so no contact can begin (5% of a 2,000-disc pile's CPU time: bench/contact.py) */
    if (A->m.w == 0.0 && B->m.w == 0.0 && dvx == 0.0 && dvy == 0.0 && A->m.ax == B->m.ax
        && A->m.ay == B->m.ay)
        return 0;
    /* can the bounding circles about the reference points meet before the current best at all?
     * (1-norm bounds of the relative speed and acceleration; a wall's circle is too large to
     * tell anything.) Most of a dense pile's pairs end here */
    if (!(B->kind == M2C_STATIC && B->nvert > 1)) {
        double T = c->t - w->now, rx, ry;
        relative_position(A, B, w->now, &rx, &ry);
        double reach = (fabs(dvx) + fabs(dvy)) * T
                       + 0.5 * (fabs(A->m.ax - B->m.ax) + fabs(A->m.ay - B->m.ay)) * T * T;
        double need = A->bound + B->bound + reach + w->cfg.tolerance;
        if (rx * rx + ry * ry > need * need * (1 + 1e-12))
            return 0;
    }
    f.a = motion_at(&A->m, w->now);
    f.b = motion_at(&B->m, w->now);
    relative_position(A, B, w->now, &f.rx, &f.ry);
    f.no_touch = 0;
    f.ghost = w->nghosts > 0 && ghost_find(w, i, j) >= 0;
    f.leaves = f.ghost && ((A->flags | B->flags) & M2C_FLAG_SENSOR);
    f.dir[0] = f.dir[1] = f.len = 0.0;
    f.solver_h = solver_window(w, A, B);
    f.shrink = 0.0;
    f.kept = pair_overlap(w, i, j, &f);
    /* several features: first the bounding circles about the reference points (exact, no
     * rotation), unless one of them is a wall's (its reference point is anywhere) */
    if ((A->nvert > 1 || B->nvert > 1) && B->kind != M2C_STATIC) {
        double p[PP_NPARAMS], cc[MAXC] = {0}, r;
        int graze = 0;
        f.pa[0] = f.pa[1] = f.pb[0] = f.pb[1] = 0.0;
        f.rot_a = f.rot_b = 0;
        fill_pp(&f, p, 0.0);
        p[R1] = A->bound;
        p[R2] = B->bound;
        int n = SLOT[0].pp.coef(p, cc);
        double tmax = c->t - w->now;
        if (cc[0] > 0) {
            if (clearly_apart(cc, n, tmax, 0.0))
                return 0;
            count_solve(w, n);
            if (m2c_first_root_ex(cc, n, tmax > 0 ? tmax : 0x1p-1074, &r, M2C_METHOD_INTERVAL, &graze) != 1)
                return 0;
        }
    }
    if (A->nparts == 1 && B->nparts == 1) {
        f.oa = f.ob = 0;
        predict_parts(&f, c);
        return c->improved;
    }
    /* a compound: every pair of parts, the earliest contact of any (each part as a body),
     * a pair of parts skipped when their bounding circles cannot meet before the best yet */
    double reach_v = fabs(f.a.vx - f.b.vx) + fabs(f.a.vy - f.b.vy);
    double reach_a = 0.5 * (fabs(f.a.ax - f.b.ax) + fabs(f.a.ay - f.b.ay));
    for (int p = 0; p < A->nparts; p++) {
        body pa = part_view(w, A, p);
        double ca[2], ra = part_circle(w, &pa, &f.a, ca);
        for (int q = 0; q < B->nparts; q++) {
            body pb = part_view(w, B, q);
            double cb[2], rb = part_circle(w, &pb, &f.b, cb);
            double T = c->t - w->now;
            double turn_a = fmin(2.0, fabs(f.a.w) * T) * hypot(ca[0], ca[1]);
            double turn_b = fmin(2.0, fabs(f.b.w) * T) * hypot(cb[0], cb[1]);
            double need = ra + rb + (reach_v + reach_a * T) * T + turn_a + turn_b
                          + w->cfg.tolerance;
            double dx = f.rx + ca[0] - cb[0], dy = f.ry + ca[1] - cb[1];
            if (dx * dx + dy * dy > need * need * (1 + 1e-12))
                continue;
            f.A = &pa;
            f.B = &pb;
            f.oa = pa.vert - A->vert;
            f.ob = pb.vert - B->vert;
            predict_parts(&f, c);
        }
    }
    return c->improved;
}
