/*
 * contact_solver.c -- sustained contact: a cluster of bodies that stays in contact is handed to a
 * constraint solver at a fixed step h and handed back to exact prediction when it separates or
 * sleeps (docs/engine-contact.md).
 *
 * Why: between impacts the engine is exact, but a body resting, sliding, rolling or tipping on
 * another touches it continuously; an event-driven engine sees that as infinitely many impacts
 * at (nearly) one instant. Frame engines solve such contacts as constraints (sequential
 * impulses / projected Gauss-Seidel with warm starting: Catto, Box2D; Chipmunk2D). We do the
 * same for the bodies that need it, and only for them:
 *
 *  - a contact closing slower than v_soft (= max(rest speed, 2 |g| h)) where one side is
 *    supported (static, kinematic, asleep or already in the solver) adopts its dynamic bodies:
 *    state SOLVING;
 *  - at each tick t = k h: v += g h; contacts (vertex-edge and vertex-vertex features with the
 *    rounding radii) within a speculative margin; PGS with Coulomb friction (|f_t| <= mu f_n,
 *    mu = sqrt(mu_a mu_b)) warm started from the last tick's impulses; the new velocities are
 *    the bodies' mean velocities until the next tick: each flies freely (gravity in its motion)
 *    along the parabola they are the chord of, evaluated exactly like every other motion, and
 *    every solver body is predicted again: any contact the
 *    linearised solve misses (a rotating corner's arc) is still an exact event, so nothing
 *    tunnels. A pair the solver holds may overlap by the slop (solver_slop, 1e-5 m at the
 *    default tolerance: Box2D's linear slop) before that event comes -- the solve meets a jammed
 *    pile's contacts only to about 1e-4 m/s -- and the overlap is pushed out again by a velocity
 *    of its own (push_sweep: split impulses) that the next tick takes off;
 *  - fast contacts (closing faster than v_soft) stay exact impacts with restitution;
 *  - a solver body with no contact for 3 ticks flies again (exact free flight);
 *  - an island (solver bodies linked by contacts) sleeps only when all of its bodies have been
 *    slower than v_sleep for t_sleep and a certificate exists: non-negative normal forces inside
 *    the friction cone that balance every body's weight and torque (solver_certify), found by
 *    projected Gauss-Seidel on the static problem and checked by summing the forces explicitly.
 *    Otherwise it keeps moving: it tips, slides, rolls or falls.
 *
 * Energy: constant between ticks (free flights); an exactly inelastic solve of the mean
 * velocities raises it by at most m (|g| h / 2)^2 / 2 per body (the hop of a body stopped on a
 * support: it leaves at |g| h / 2 and lands at the next tick); pushing an overlap (never deeper
 * than the slop) back out raises a body by at most the slop: m |g| slop per contact (the
 * push's velocity is no momentum: it is taken off at the next tick). docs/engine-contact.md.
 */
#include <float.h>
#include <stdint.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine.h"

#define DEFAULT_STEP (1.0 / 240.0) /* suggested */
#define IDLE_TICKS 3          /* ticks with no contact before a body flies again */
#define SLEEP_TIME 0.25       /* seconds slower than v_sleep before an island may sleep */
#define CERT_RESIDUAL 1e-6    /* certificate: unbalanced force / weight (and torque / (weight rho)) */
#define CERT_ITERATIONS 4000
#define CHECK_ITERATIONS 20000 /* World.certificate's check of an asleep island: no tick's forces
                                 to start from, and no hurry (a 200-disc pile that slept
                                 certified met 1.6e-6 .. 6.4e-6 after 4,000 from zero) */
#define CERT_OMEGA 1.8        /* over-relaxation of the certificate's normal forces (SOR) */
#define TICK_OMEGA 1.8        /* over-relaxation of the tick's normal impulses: a jittered
                                 column of 10 boxes met CONVERGED in 1,500-2,000 sweeps a
                                 tick with 1.0 (a chain's slow mode), in 300-450 with 1.8 */
#define PLAIN_SWEEPS 50       /* pgs: sweeps before the over-relaxation (at most a quarter of
                                 the limit): over-relaxed from the first, a box tipping onto a
                                 floor (two contacts, which plain sweeps meet in a few) needed
                                 5-56x the sweeps (0.8 a sweep at best) */
#define CERT_WAIT_BODIES 25   /* a failed certificate waits 0.125 s more per this many bodies */
#define WORK_BUDGET 50000     /* PGS contact updates per tick (iterations = budget / contacts):
                                 a dense pile never meets CONVERGED (its slow mode), so this
                                 is its cost; 200,000 slept no sooner (bench/contact.py) */
#define MIN_ITERATIONS 10
#define MAX_ITERATIONS 2000
#define CONVERGED 1e-9        /* a sweep that changes no impulse by more than this of m |g| h */
#define SLOP_TOLERANCES 1e4   /* solver_slop */
#define PUSH_OUT 0.8          /* of an overlap pushed out per tick (push_sweep) */
#define PUSH_CONVERGED 1e-6   /* the push-out's sweeps stop at this of m |g| h (push_sweep) */
#define LOCAL_BODIES 64       /* bodies solved together at a soft contact between ticks */
#define INSTANT_CONTACTS 8    /* soft contacts remembered through one instant (remember_instant) */

typedef struct {
    int a, b;                 /* a: in the solve; b: in the solve too when free_b */
    int free_b;
    unsigned key;             /* feature key: warm starting matches (a, b, key) */
    double n[2];              /* from a towards b */
    double ra[2], rb[2];      /* arms from the reference points to the contact point */
    double ka[2], kb[2];      /* the arms' cross products with n and t (arms): a circle's
                                 normal one exactly 0 */
    double vb[2];             /* a fixed b's contact point velocity */
    double gap;
    double mn, mt;            /* effective masses along n and t */
    double ln, lt;            /* accumulated impulses */
    double bias;              /* the least relative normal velocity allowed */
    double mu;
    double lp, push;          /* the push-out: its impulse and target speed (push_out) */
} cp;

struct solver {
    double h, t_next;
    int *list, n;             /* the solver bodies, in adoption order */
    int *slot;                /* per body: its index in list, or -1 */
    double *calm;             /* per body: time spent slower than v_sleep */
    int *idle;                /* per body: ticks without a contact */
    int *uf;                  /* per body: union-find parent (islands) */
    int *mark;                /* per body: island membership (certificates) */
    int *flag;                /* per body: 1 touches, 2 supported, 4 touches a mover */
    double *v;                /* per body: vx, vy, w during a solve */
    double *vp;               /* per body: the push-out's velocity in its motion since the tick */
    unsigned *pc;             /* per body: its motion counter when the tick set that motion */
    int bcap;
    cp *c, *prev;
    int nc, capc, nprev, capprev;
    int *hash;                /* open addressing over prev: warm starting */
    int hcap;
    struct {                  /* the soft contacts met at the instant inst_t, by the features */
        int a, b;             /* the prediction met (remember_instant): a ring of the last few */
        event ev;
    } inst[INSTANT_CONTACTS];
    int ninst, next_inst;
    double inst_t;
};

static double cross(const double a[2], const double b[2])
{
    return a[0] * b[1] - a[1] * b[0];
}

/* Is body B one circle about its reference point? Its contacts' normals pass through its
 * centre: a normal impulse turns it by nothing, not by the rounding of cross(r, n) (200
 * frictionless discs of bench/contact.py all spun, at up to 2e-12 rad/s after 2.5 s, and every
 * motion_at of a spinning body costs a sine and a cosine: 8% of a 300-disc pile's time). */
int centred_circle(const m2c_world *w, const body *B)
{
    return B->nvert == 1 && B->nparts == 1 && w->verts[2 * B->vert] == 0.0
           && w->verts[2 * B->vert + 1] == 0.0;
}

/* c's ka, kb from its arms and normal (c->a, c->b its bodies). */
static void arms(const m2c_world *w, cp *c)
{
    double t[2] = {-c->n[1], c->n[0]};
    c->ka[0] = centred_circle(w, &w->b[c->a]) ? 0.0 : cross(c->ra, c->n);
    c->ka[1] = cross(c->ra, t);
    c->kb[0] = centred_circle(w, &w->b[c->b]) ? 0.0 : cross(c->rb, c->n);
    c->kb[1] = cross(c->rb, t);
}

double solver_step(const m2c_world *w)
{
    double h = w->cfg.contact_step;
    return h > 0 ? h : -1.0; /* (0 in C's zeroed config: off; Python's default: DEFAULT_STEP) */
}

/* The overlap a pair the solver holds may keep without an exact event (predict.c's
 * feature_slop): SLOP_TOLERANCES tolerances (1e-5 m at the default 1e-9), as Box2D's linear
 * slop; the ticks push any overlap out again. 0 with the solver off. */
double solver_slop(const m2c_world *w)
{
    return solver_step(w) > 0 ? SLOP_TOLERANCES * w->cfg.tolerance : 0.0;
}

/* The gap within which a contact counts for a certificate (and for support): 1,000
 * tolerances, or the slop where that is larger (a pair the solver holds may sit that far in
 * or out of touch from one tick to the next). */
static double cert_gap(const m2c_world *w)
{
    return fmax(1e3 * w->cfg.tolerance, solver_slop(w));
}

static double glen(const body *b)
{
    return hypot(b->gx, b->gy);
}

double solver_soft_speed(const m2c_world *w, const body *b)
{
    double g = glen(b), h = solver_step(w);
    if (!(h > 0) || !(g > 0))
        return -1.0;
    double vr = rest_speed(w, g);
    return fmax(vr, 2 * g * h);
}

static double sleep_speed(const m2c_world *w, const body *b)
{
    double g = glen(b);
    return fmax(rest_speed(w, g), g * solver_step(w));
}

static int ensure(m2c_world *w)
{
    struct solver *s = w->solver;
    if (!s) {
        s = calloc(1, sizeof *s);
        if (!s)
            return -1;
        s->t_next = INFINITY;
        w->solver = s;
    }
    if (s->bcap < w->cap) {
        int cap = w->cap;
        int *list = realloc(s->list, sizeof(int) * (size_t)cap);
        int *slot = realloc(s->slot, sizeof(int) * (size_t)cap);
        double *calm = realloc(s->calm, sizeof(double) * (size_t)cap);
        int *idle = realloc(s->idle, sizeof(int) * (size_t)cap);
        int *uf = realloc(s->uf, sizeof(int) * (size_t)cap);
        int *mark = realloc(s->mark, sizeof(int) * (size_t)cap);
        int *flag = realloc(s->flag, sizeof(int) * (size_t)cap);
        if (flag)
            s->flag = flag;
        double *v = realloc(s->v, sizeof(double) * 3 * (size_t)cap);
        double *vp = realloc(s->vp, sizeof(double) * 3 * (size_t)cap);
        if (vp)
            s->vp = vp;
        unsigned *pc = realloc(s->pc, sizeof(unsigned) * (size_t)cap);
        if (pc)
            s->pc = pc;
        if (list)
            s->list = list;
        if (slot)
            s->slot = slot;
        if (calm)
            s->calm = calm;
        if (idle)
            s->idle = idle;
        if (uf)
            s->uf = uf;
        if (mark)
            s->mark = mark;
        if (v)
            s->v = v;
        if (!list || !slot || !calm || !idle || !uf || !mark || !flag || !v || !vp || !pc)
            return -1;
        for (int i = s->bcap; i < cap; i++) {
            s->slot[i] = -1;
            s->mark[i] = 0;
            s->flag[i] = 0;
        }
        s->bcap = cap;
    }
    return 0;
}

void solver_free(m2c_world *w)
{
    struct solver *s = w->solver;
    if (!s)
        return;
    free(s->list);
    free(s->slot);
    free(s->calm);
    free(s->idle);
    free(s->uf);
    free(s->mark);
    free(s->flag);
    free(s->v);
    free(s->vp);
    free(s->pc);
    free(s->c);
    free(s->prev);
    free(s->hash);
    free(s);
    w->solver = NULL;
}

double solver_next_tick(const m2c_world *w)
{
    const struct solver *s = w->solver;
    return s && s->n > 0 ? s->t_next : INFINITY;
}

int solver_count(const m2c_world *w)
{
    return w->solver ? w->solver->n : 0;
}

int solver_has(const m2c_world *w, int i)
{
    return w->b[i].kind == M2C_DYNAMIC && w->b[i].state == SOLVING;
}

/* Hand dynamic body k to the solver (from now on its gravity is applied at the ticks). */
int solver_adopt(m2c_world *w, int k)
{
    body *K = &w->b[k];
    if (K->kind != M2C_DYNAMIC || K->state == SOLVING || !(solver_step(w) > 0))
        return 0;
    if (ensure(w) != 0)
        return 0;
    struct solver *s = w->solver;
    body_commit(K, w->now);
    K->state = SOLVING;
    K->m.ax = K->gx; /* gravity stays in its motion (exact flight between ticks) */
    K->m.ay = K->gy;
    K->support = -1;
    K->rest_time = NAN;
    K->burst = K->instant = 0;
    K->elastic = 0;
    K->counter++;
    s->slot[k] = s->n;
    s->list[s->n++] = k;
    s->calm[k] = 0.0;
    s->idle[k] = 0;
    s->vp[3 * k] = s->vp[3 * k + 1] = s->vp[3 * k + 2] = 0.0;
    s->pc[k] = K->counter;
    s->uf[k] = k; /* (an island of its own until the next tick links it) */
    if (s->n == 1 || !(s->t_next > w->now)) {
        double h = solver_step(w);
        double t = ceil(w->now / h) * h;
        s->t_next = t > w->now ? t : t + h;
    }
    return 1;
}

/* Back to exact prediction: gravity in the motion again. */
static void release(m2c_world *w, int k)
{
    struct solver *s = w->solver;
    body *K = &w->b[k];
    int at = s->slot[k];
    s->list[at] = s->list[--s->n];
    s->slot[s->list[at]] = at;
    s->slot[k] = -1;
    body_commit(K, w->now);
    K->state = AWAKE;
    K->m.ax = K->gx;
    K->m.ay = K->gy;
    K->counter++;
}

/* Body k leaves the solver (an edit: removed, kind or motion changed): exact flight again. */
static int push_contact(m2c_world *w, cp *c);

void solver_forget(m2c_world *w, int k)
{
    if (w->solver && k >= 0 && k < w->n && w->solver->slot[k] >= 0)
        release(w, k);
}

/* -------------------------------------------------------------------------------------------
 * Snapshots (snapshot.c): the solver's lasting state -- its step, next tick, bodies with their
 * calm times and idle ticks, and the last tick's contacts with their impulses (warm starting)
 * -- so that a loaded world ticks exactly as the saved one would. The rest is scratch.
 */

void solver_save(const m2c_world *w, void (*put)(void *, const void *, size_t), void *ctx)
{
    const struct solver *s = w->solver;
    int32_t counts[2] = {s ? s->n : 0, s ? s->nc : 0};
    put(ctx, counts, sizeof counts);
    if (!s)
        return;
    put(ctx, &s->h, sizeof s->h);
    put(ctx, &s->t_next, sizeof s->t_next);
    put(ctx, s->list, sizeof(int) * (size_t)s->n);
    for (int m = 0; m < s->n; m++) {
        put(ctx, &s->calm[s->list[m]], sizeof(double));
        put(ctx, &s->idle[s->list[m]], sizeof(int));
        put(ctx, &s->vp[3 * s->list[m]], 3 * sizeof(double));
        put(ctx, &s->pc[s->list[m]], sizeof(unsigned));
    }
    put(ctx, s->c, sizeof(cp) * (size_t)s->nc);
    put(ctx, &s->ninst, sizeof s->ninst);
    put(ctx, &s->next_inst, sizeof s->next_inst);
    put(ctx, &s->inst_t, sizeof s->inst_t);
    put(ctx, s->inst, sizeof s->inst[0] * (size_t)s->ninst);
}

int solver_load(m2c_world *w, int (*get)(void *, void *, size_t), void *ctx)
{
    int32_t counts[2];
    w->solver = NULL;
    if (get(ctx, counts, sizeof counts) != 0 || counts[0] < 0 || counts[0] > w->n || counts[1] < 0)
        return -1;
    if (counts[0] == 0 && counts[1] == 0)
        return 0;
    if (ensure(w) != 0)
        return -1;
    struct solver *s = w->solver;
    if (get(ctx, &s->h, sizeof s->h) != 0 || get(ctx, &s->t_next, sizeof s->t_next) != 0)
        return -1;
    for (int m = 0; m < counts[0]; m++) {
        int k;
        if (get(ctx, &k, sizeof k) != 0 || k < 0 || k >= w->n || s->slot[k] >= 0
            || !solver_has(w, k))
            return -1;
        s->slot[k] = m;
        s->list[s->n++] = k;
    }
    for (int m = 0; m < s->n; m++)
        if (get(ctx, &s->calm[s->list[m]], sizeof(double)) != 0
            || get(ctx, &s->idle[s->list[m]], sizeof(int)) != 0
            || get(ctx, &s->vp[3 * s->list[m]], 3 * sizeof(double)) != 0
            || get(ctx, &s->pc[s->list[m]], sizeof(unsigned)) != 0)
            return -1;
    for (int k = 0; k < counts[1]; k++) {
        cp c;
        if (get(ctx, &c, sizeof c) != 0 || c.a < 0 || c.a >= w->n || c.b < 0 || c.b >= w->n
            || push_contact(w, &c) != 0)
            return -1;
    }
    if (get(ctx, &s->ninst, sizeof s->ninst) != 0 || get(ctx, &s->next_inst, sizeof s->next_inst) != 0
        || get(ctx, &s->inst_t, sizeof s->inst_t) != 0 || s->ninst < 0 || s->ninst > INSTANT_CONTACTS
        || s->next_inst < 0 || s->next_inst >= INSTANT_CONTACTS
        || get(ctx, s->inst, sizeof s->inst[0] * (size_t)s->ninst) != 0)
        return -1;
    for (int m = 0; m < s->ninst; m++)
        if (s->inst[m].a < 0 || s->inst[m].a >= w->n || s->inst[m].b < 0 || s->inst[m].b >= w->n)
            return -1;
    return 0;
}

/* -------------------------------------------------------------------------------------------
 * Contacts: every vertex (with its rounding radius) against every edge and vertex of the other
 * body, within `margin`, where the normal lies in the vertex's normal cone (else a box's side
 * corner would "touch" the floor through the box).
 */

typedef struct {
    m2c_world *w;
    double margin_base;      /* added to every pair's speculative margin */
    int only_members;        /* certificate: partners that are members (mark) or not dynamic */
    int fail;                /* certificate: touched an awake dynamic non-member */
} gen_ctx;

static int push_contact(m2c_world *w, cp *c)
{
    struct solver *s = w->solver;
    if (s->nc == s->capc) {
        int cap = s->capc ? 2 * s->capc : 256;
        cp *n = realloc(s->c, sizeof(cp) * (size_t)cap);
        if (!n)
            return -1;
        s->c = n;
        s->capc = cap;
    }
    s->c[s->nc++] = *c;
    return 0;
}

/* Is direction d in the outward normal cone of vertex v of body B (at snapshot sn), or within
 * SOLVER_CONE_SLACK (a sine) of it? The slack keeps a box's corner on a floor when the box tilts a
 * little the other way (at 1e-6 the lifted corner lost its contact, in the ticks and in
 * predict.c alike, and a column sank); a side met at right angles stays out. */
int solver_in_cone(const m2c_world *w, const body *B, const snap *sn, int v, const double d[2])
{
    if (B->nvert == 1)
        return 1;
    double P[2];
    world_point(sn, &w->verts[2 * (B->vert + v)], P);
    int nb[2], cnt = 0;
    if (B->nvert == 2) {
        nb[cnt++] = 1 - v;
    } else {
        nb[cnt++] = (v + B->nvert - 1) % B->nvert;
        nb[cnt++] = (v + 1) % B->nvert;
    }
    for (int k = 0; k < cnt; k++) {
        double Q[2];
        world_point(sn, &w->verts[2 * (B->vert + nb[k])], Q);
        double e[2] = {P[0] - Q[0], P[1] - Q[1]};
        if (d[0] * e[0] + d[1] * e[1] < -SOLVER_CONE_SLACK * hypot(e[0], e[1]))
            return 0;
    }
    return 1;
}

static void point_velocity(const snap *s, const double r[2], double out[2])
{
    out[0] = s->vx - s->w * r[1];
    out[1] = s->vy + s->w * r[0];
}

/* One contact: point P of body `pa` (index i), normal n from i towards j, gap, contact point. */
static void add_one(m2c_world *w, int i, int j, const double n[2], const double p[2], double gap,
                    unsigned key)
{
    struct solver *s = w->solver;
    const body *A = &w->b[i], *B = &w->b[j];
    snap sa = motion_at(&A->m, w->now), sb = motion_at(&B->m, w->now);
    cp c;
    memset(&c, 0, sizeof c);
    c.a = i;
    c.b = j;
    c.free_b = B->kind == M2C_DYNAMIC && B->state == SOLVING;
    c.key = key;
    c.n[0] = n[0];
    c.n[1] = n[1];
    c.ra[0] = p[0] - sa.x;
    c.ra[1] = p[1] - sa.y;
    c.rb[0] = p[0] - sb.x;
    c.rb[1] = p[1] - sb.y;
    if (!c.free_b) {
        if (B->kind == M2C_DYNAMIC && B->state != ASLEEP && !body_still(B))
            point_velocity(&sb, c.rb, c.vb);   /* an awake body outside: moves as it moves */
        else if (B->kind == M2C_KINEMATIC)
            point_velocity(&sb, c.rb, c.vb);
    }
    c.gap = gap;
    double ima = A->inv_mass, iia = A->inv_inertia;
    double imb = c.free_b ? B->inv_mass : 0.0, iib = c.free_b ? B->inv_inertia : 0.0;
    arms(w, &c);
    double rna = c.ka[0], rnb = c.kb[0], rta = c.ka[1], rtb = c.kb[1];
    double kn = ima + imb + iia * rna * rna + iib * rnb * rnb;
    double kt = ima + imb + iia * rta * rta + iib * rtb * rtb;
    c.mn = kn > 0 ? 1 / kn : 0.0;
    c.mt = kt > 0 ? 1 / kt : 0.0;
    c.mu = sqrt(A->friction * B->friction);
    (void)s;
    push_contact(w, &c);
}

/* Contacts between a part of body i and a part of body j (both orders of vertex against edge;
 * vertex against vertex): the parts as bodies (part_view), o0 and o1 their first vertices'
 * body-level indices (the contacts' keys name body-level vertices and edges). */
/* Do two vertices d2 apart (squared) with radii summing to R come within margin of touching?
 * 1 and their distance; the one test of gen_parts' vertex-against-vertex contacts and of the
 * wedge rule's flood between two circles (flood_visit), which builds no contact. */
static int vertices_within(double d2, double R, double margin, double *dist)
{
    if (!(d2 > 0) || d2 > (R + margin) * (R + margin) * (1 + 1e-12))
        return 0;
    *dist = sqrt(d2);
    return !(*dist - R > margin);
}

static void gen_parts(m2c_world *w, int i, int j, const body *P0, const body *P1, int o0, int o1,
                      double margin)
{
    const body *B[2] = {P0, P1};
    int id[2] = {i, j}, off[2] = {o0, o1};
    snap sn[2] = {motion_at(&B[0]->m, w->now), motion_at(&B[1]->m, w->now)};
    double R = B[0]->radius + B[1]->radius;
    /* quick reject on the bounding circles (squared: glibc's hypot was 11% of a 500-disc
     * pile's time, most of it here and below) */
    double dx = sn[1].x - sn[0].x, dy = sn[1].y - sn[0].y, reach = B[0]->bound + B[1]->bound + margin;
    if (B[1]->kind == M2C_DYNAMIC && dx * dx + dy * dy > reach * reach)
        return;
    for (int side = 0; side < 2; side++) {
        const body *P = B[side], *E = B[1 - side];
        const snap *sp = &sn[side], *se = &sn[1 - side];
        int nedges = E->nvert >= 3 ? E->nvert : E->nvert - 1;
        for (int v = 0; v < P->nvert; v++) {
            double X[2];
            world_point(sp, &w->verts[2 * (P->vert + v)], X);
            for (int u = 0; u < nedges; u++) {
                double L[2], D[2];
                const double *e = &w->edges[3 * (E->vert + u)];
                world_point(se, &w->verts[2 * (E->vert + u)], L);
                world_vector(se, e, D);
                double rel[2] = {X[0] - L[0], X[1] - L[1]};
                double along = rel[0] * D[0] + rel[1] * D[1];
                if (along < 0 || along > e[2])
                    continue;
                double across = rel[0] * D[1] - rel[1] * D[0]; /* > 0: outside (anticlockwise) */
                double sgn = 1.0;
                if (E->nvert == 2) { /* a segment has two sides: the one the body's centre is on */
                    double cc[2] = {sp->x - L[0], sp->y - L[1]};
                    sgn = cc[0] * D[1] - cc[1] * D[0] >= 0 ? 1.0 : -1.0;
                }
                double gap = sgn * across - R;
                if (gap > margin || gap < -R - 1e-3 * (P->bound + E->bound) - 1e-9)
                    continue;
                double out[2] = {sgn * D[1], -sgn * D[0]}; /* the edge's outward normal */
                double d[2] = {-out[0], -out[1]};          /* from the vertex into the edge */
                if (!solver_in_cone(w, P, sp, v, d))
                    continue;
                double p[2] = {X[0] - out[0] * P->radius, X[1] - out[1] * P->radius};
                /* normal from i towards j */
                double n[2] = {side == 0 ? d[0] : out[0], side == 0 ? d[1] : out[1]};
                unsigned key = (unsigned)(side << 30) | (unsigned)((v + off[side]) << 15)
                               | (unsigned)(u + off[1 - side]);
                add_one(w, id[0], id[1], n, p, gap, key);
            }
        }
    }
    /* vertex against vertex: rounded corners and circles */
    if (R > 0 || (B[0]->nvert == 1 || B[1]->nvert == 1)) {
        for (int v = 0; v < B[0]->nvert; v++) {
            double X[2];
            world_point(&sn[0], &w->verts[2 * (B[0]->vert + v)], X);
            for (int u = 0; u < B[1]->nvert; u++) {
                double Y[2];
                world_point(&sn[1], &w->verts[2 * (B[1]->vert + u)], Y);
                double d[2] = {Y[0] - X[0], Y[1] - X[1]}, d2 = d[0] * d[0] + d[1] * d[1], dist;
                if (!vertices_within(d2, R, margin, &dist))
                    continue;
                double gap = dist - R;
                double n[2] = {d[0] / dist, d[1] / dist}, m[2] = {-n[0], -n[1]};
                if (!solver_in_cone(w, B[0], &sn[0], v, n) || !solver_in_cone(w, B[1], &sn[1], u, m))
                    continue;
                /* the edge features cover the interior of a cone's sides: skip when the normal
                 * is an edge's normal (the vertex-edge contact is already there) */
                int covered = 0;
                for (int side = 0; side < 2 && !covered; side++) {
                    const body *E = B[1 - side];
                    if (E->nvert < 2)
                        continue;
                    int nedges = E->nvert >= 3 ? E->nvert : E->nvert - 1;
                    const snap *se = &sn[1 - side];
                    const double *vx = side == 0 ? X : Y;
                    for (int k = 0; k < nedges && !covered; k++) {
                        double L[2], D[2];
                        const double *e = &w->edges[3 * (E->vert + k)];
                        world_point(se, &w->verts[2 * (E->vert + k)], L);
                        world_vector(se, e, D);
                        double along = (vx[0] - L[0]) * D[0] + (vx[1] - L[1]) * D[1];
                        if (along >= 0 && along <= e[2])
                            covered = 1;
                    }
                }
                if (covered)
                    continue;
                double p[2] = {X[0] + n[0] * B[0]->radius, X[1] + n[1] * B[0]->radius};
                unsigned key = (3u << 30) | (unsigned)((v + o0) << 15) | (unsigned)(u + o1);
                add_one(w, i, j, n, p, gap, key);
            }
        }
    }
}

/* Contacts between bodies i and j: every pair of their parts. */
static void gen_pair(m2c_world *w, int i, int j, double margin)
{
    const body *A = &w->b[i], *B = &w->b[j];
    if (A->nparts == 1 && B->nparts == 1) {
        gen_parts(w, i, j, A, B, 0, 0, margin);
        return;
    }
    for (int p = 0; p < A->nparts; p++) {
        body u = part_view(w, A, p);
        for (int q = 0; q < B->nparts; q++) {
            body v = part_view(w, B, q);
            gen_parts(w, i, j, &u, &v, u.vert - A->vert, v.vert - B->vert, margin);
        }
    }
}

static double body_speed(const body *b, const double *v)
{
    return sqrt(v[0] * v[0] + v[1] * v[1]) + fabs(v[2]) * b->rho;
}

/* The fastest point of the body's surface (a ball's rim too: a ball spinning on the spot is
 * not calm, whatever its centre does). */
static double surface_speed(const body *b, const double *v)
{
    return sqrt(v[0] * v[0] + v[1] * v[1]) + fabs(v[2]) * fmax(b->rho, b->bound);
}

/* A position at now, as motion_at computes it (bit for bit) */
static inline double pos_at(double x, double v, double a, double s)
{
    return x + s * (v + 0.5 * a * s);
}

/* Are solver body i and dynamic body j (one part each, j solving or asleep) farther apart than
 * gen_parts' bounding circles with any margin gen_visit could give them? A bound of that margin
 * from 1-norms of the velocities (no square roots, no motions evaluated), with room for
 * rounding: a pair rejected here gen_parts rejects too (most of a dense pile's grid
 * neighbours: about 49 a body in the 200 discs of bench/contact.py, 6 touching). */
static int cheap_apart(const m2c_world *w, const struct solver *s, int i, int j, double base)
{
    const body *I = &w->b[i], *J = &w->b[j];
    if (I->nparts != 1 || J->nparts != 1 || J->kind != M2C_DYNAMIC
        || (J->state != SOLVING && J->state != ASLEEP))
        return 0;
    double si = w->now - I->m.t, sj = w->now - J->m.t;
    double dx = pos_at(J->m.x, J->m.vx, J->m.ax, sj) - pos_at(I->m.x, I->m.vx, I->m.ax, si);
    double dy = pos_at(J->m.y, J->m.vy, J->m.ay, sj) - pos_at(I->m.y, I->m.vy, I->m.ay, si);
    const double *vi = &s->v[3 * i];
    double speed = fabs(vi[0]) + fabs(vi[1]) + fabs(vi[2]) * I->rho;
    if (J->state == SOLVING) {
        const double *vj = &s->v[3 * j];
        speed += fabs(vj[0]) + fabs(vj[1]) + fabs(vj[2]) * J->rho;
    }
    double reach = (I->bound + J->bound + base + s->h * speed) * (1 + 1e-9);
    return dx * dx + dy * dy > reach * reach;
}

static void gen_visit(m2c_world *w, int i, int j, void *ctx)
{
    gen_ctx *g = ctx;
    struct solver *s = w->solver;
    const body *J = &w->b[j];
    if (J->kind == M2C_DYNAMIC && J->state == SOLVING && j < i && !g->only_members)
        return; /* the pair is generated from j's side */
    if (g->only_members && s->mark[j] && j < i)
        return;
    if (J->group >= 0 && J->group == w->b[i].group)
        return;
    double margin = g->margin_base;
    if (!g->only_members && J->kind == M2C_DYNAMIC && J->state != SOLVING && J->state != ASLEEP)
        return; /* a body in flight: its contacts are exact events (slow ones bring it in) */
    if (!g->only_members && cheap_apart(w, s, i, j, margin))
        return; /* gen_parts' first test would say so, at more cost */
    if (!g->only_members) {
        const body *I = &w->b[i];
        double vj[3] = {0, 0, 0};
        if (J->kind != M2C_STATIC && !(J->kind == M2C_DYNAMIC && J->state == ASLEEP)) {
            snap sj = motion_at(&J->m, w->now);
            vj[0] = sj.vx;
            vj[1] = sj.vy;
            vj[2] = sj.w;
            if (J->state == SOLVING) {
                vj[0] = s->v[3 * j];
                vj[1] = s->v[3 * j + 1];
                vj[2] = s->v[3 * j + 2];
            }
        }
        margin += s->h * (body_speed(I, &s->v[3 * i]) + body_speed(J, vj));
    } else if (J->kind == M2C_DYNAMIC && !s->mark[j] && J->state != ASLEEP) {
        /* a moving body outside the island touches it: no certificate unless it is apart */
        int before = w->solver->nc;
        gen_pair(w, i, j, margin);
        if (w->solver->nc > before) {
            g->fail = 1;
            w->solver->nc = before;
        }
        return;
    }
    gen_pair(w, i, j, margin);
}

/* -------------------------------------------------------------------------------------------
 * Projected Gauss-Seidel. v: per body (vx, vy, w); contacts' impulses ln, lt accumulate.
 */

static inline __attribute__((always_inline)) void apply(struct solver *s, const m2c_world *w,
                                                        const cp *c, double Pn, double Pt)
{
    double t[2] = {-c->n[1], c->n[0]};
    double P[2] = {Pn * c->n[0] + Pt * t[0], Pn * c->n[1] + Pt * t[1]};
    const body *A = &w->b[c->a];
    double *va = &s->v[3 * c->a];
    va[0] -= P[0] * A->inv_mass;
    va[1] -= P[1] * A->inv_mass;
    va[2] -= (c->ka[0] * Pn + c->ka[1] * Pt) * A->inv_inertia;
    if (c->free_b) {
        const body *B = &w->b[c->b];
        double *vb = &s->v[3 * c->b];
        vb[0] += P[0] * B->inv_mass;
        vb[1] += P[1] * B->inv_mass;
        vb[2] += (c->kb[0] * Pn + c->kb[1] * Pt) * B->inv_inertia;
    }
}

static inline __attribute__((always_inline)) void rel_velocity(const struct solver *s,
                                                               const cp *c, double out[2])
{
    const double *va = &s->v[3 * c->a];
    double ua[2] = {va[0] - va[2] * c->ra[1], va[1] + va[2] * c->ra[0]};
    double ub[2] = {c->vb[0], c->vb[1]};
    if (c->free_b) {
        const double *vb = &s->v[3 * c->b];
        ub[0] = vb[0] - vb[2] * c->rb[1];
        ub[1] = vb[1] + vb[2] * c->rb[0];
    }
    out[0] = ub[0] - ua[0];
    out[1] = ub[1] - ua[1];
}

/* One sweep; returns the largest impulse change. */
static double sweep(struct solver *s, const m2c_world *w, cp *c, int nc, int friction, double omega)
{
    double worst = 0.0;
    for (int k = 0; k < nc; k++) {
        cp *q = &c[k];
        double u[2];
        if (friction && q->mu > 0) {
            rel_velocity(s, q, u);
            double t[2] = {-q->n[1], q->n[0]};
            double vt = u[0] * t[0] + u[1] * t[1];
            double lim = q->mu * q->ln;
            double nl = q->lt - vt * q->mt;
            nl = nl > lim ? lim : nl < -lim ? -lim : nl;
            double d = nl - q->lt;
            if (d != 0.0) {
                q->lt = nl;
                apply(s, w, q, 0.0, d);
                worst = fmax(worst, fabs(d));
            }
        }
        rel_velocity(s, q, u);
        double vn = u[0] * q->n[0] + u[1] * q->n[1];
        double nl = q->ln + omega * (q->bias - vn) * q->mn;
        if (nl < 0)
            nl = 0;
        double d = nl - q->ln;
        if (d != 0.0) {
            q->ln = nl;
            apply(s, w, q, d, 0.0);
            worst = fmax(worst, fabs(d));
        }
    }
    return worst;
}

/* The push-out (split impulses, as Box2D v2 and Bullet): an overlap is pushed out by
 * PUSH_OUT of its depth per tick (a gap may close) through a velocity
 * vp of its own, solved like the normal impulses (no friction) but kept out of the bodies'
 * momentum: it moves them until the next tick, which takes it off again. Pushing the overlap
 * out through the real velocity (Baumgarte) kept it as motion: a column of boxes swayed and a
 * pile boiled, never calm enough to sleep, and energy rose. Returns the largest change. */
static double push_sweep(struct solver *s, const m2c_world *w, cp *c, int nc)
{
    double worst = 0.0;
    for (int k = 0; k < nc; k++) {
        cp *q = &c[k];
        const body *A = &w->b[q->a], *B = &w->b[q->b];
        double *va = &s->vp[3 * q->a], *vb = q->free_b ? &s->vp[3 * q->b] : NULL;
        double vn = -(va[0] * q->n[0] + va[1] * q->n[1] + va[2] * q->ka[0]);
        if (vb)
            vn += vb[0] * q->n[0] + vb[1] * q->n[1] + vb[2] * q->kb[0];
        double nl = q->lp + (q->push - vn) * q->mn;
        if (nl < 0)
            nl = 0;
        double d = nl - q->lp;
        if (d == 0.0)
            continue;
        q->lp = nl;
        double P[2] = {d * q->n[0], d * q->n[1]};
        va[0] -= P[0] * A->inv_mass;
        va[1] -= P[1] * A->inv_mass;
        va[2] -= q->ka[0] * d * A->inv_inertia;
        if (vb) {
            vb[0] += P[0] * B->inv_mass;
            vb[1] += P[1] * B->inv_mass;
            vb[2] += q->kb[0] * d * B->inv_inertia;
        }
        worst = fmax(worst, fabs(d));
    }
    return worst;
}

/* Iterate until the largest impulse change is below eps or `limit` sweeps: the first
 * min(PLAIN_SWEEPS, limit / 4) plain, then with omega over-relaxing the normal impulses
 * (sweep). */
static int pgs(struct solver *s, const m2c_world *w, cp *c, int nc, int limit, double eps,
               double omega)
{
    int plain = limit / 4 < PLAIN_SWEEPS ? limit / 4 : PLAIN_SWEEPS, it;
    for (it = 0; it < limit; it++)
        if (sweep(s, w, c, nc, 1, it < plain ? 1.0 : omega) <= eps)
            break;
    return it;
}

/* -------------------------------------------------------------------------------------------
 * Warm starting: last tick's impulses of the same (a, b, feature).
 */

static unsigned hash3(int a, int b, unsigned key)
{
    unsigned h = (unsigned)a * 2654435761u ^ (unsigned)b * 40503u ^ key * 2246822519u;
    return h ^ (h >> 15);
}

static void remember(struct solver *s)
{
    cp *t = s->prev;
    int cap = s->capprev;
    s->prev = s->c;
    s->capprev = s->capc;
    s->nprev = s->nc;
    s->c = t;
    s->capc = cap;
    s->nc = 0;
    int want = 16;
    while (want < 2 * s->nprev)
        want *= 2;
    if (want > s->hcap) {
        int *h = realloc(s->hash, sizeof(int) * (size_t)want);
        if (!h) {
            s->nprev = 0;
            return;
        }
        s->hash = h;
        s->hcap = want;
    }
    for (int k = 0; k < s->hcap; k++)
        s->hash[k] = -1;
    for (int k = 0; k < s->nprev; k++) {
        const cp *q = &s->prev[k];
        unsigned h = hash3(q->a, q->b, q->key) & (unsigned)(s->hcap - 1);
        while (s->hash[h] >= 0)
            h = (h + 1) & (unsigned)(s->hcap - 1);
        s->hash[h] = k;
    }
}

static const cp *recall(const struct solver *s, const cp *c)
{
    if (s->nprev == 0 || s->hcap == 0)
        return NULL;
    unsigned h = hash3(c->a, c->b, c->key) & (unsigned)(s->hcap - 1);
    while (s->hash[h] >= 0) {
        const cp *q = &s->prev[s->hash[h]];
        if (q->a == c->a && q->b == c->b && q->key == c->key)
            return q;
        h = (h + 1) & (unsigned)(s->hcap - 1);
    }
    return NULL;
}

/* -------------------------------------------------------------------------------------------
 * Islands and the sleep certificate.
 */

static int find(int *uf, int x)
{
    while (uf[x] != x) {
        uf[x] = uf[uf[x]];
        x = uf[x];
    }
    return x;
}

/* The worst unbalanced force (relative to the weight) and torque (relative to weight x rho)
 * of the marked bodies under the contact forces c[].ln, c[].lt (forces: the static problem is
 * solved with h = 1). */
static double residual(m2c_world *w, const cp *c, int nc, const int *bodies, int nb)
{
    struct solver *s = w->solver;
    for (int m = 0; m < nb; m++) {
        int i = bodies[m];
        const body *B = &w->b[i];
        s->v[3 * i] = B->mass * B->gx;
        s->v[3 * i + 1] = B->mass * B->gy;
        s->v[3 * i + 2] = 0.0;
    }
    for (int k = 0; k < nc; k++) {
        const cp *q = &c[k];
        double t[2] = {-q->n[1], q->n[0]};
        double F[2] = {q->ln * q->n[0] + q->lt * t[0], q->ln * q->n[1] + q->lt * t[1]};
        double *fa = &s->v[3 * q->a];
        fa[0] -= F[0];
        fa[1] -= F[1];
        fa[2] -= cross(q->ra, F);
        if (q->free_b) {
            double *fb = &s->v[3 * q->b];
            fb[0] += F[0];
            fb[1] += F[1];
            fb[2] += cross(q->rb, F);
        }
    }
    double worst = 0.0;
    for (int m = 0; m < nb; m++) {
        int i = bodies[m];
        const body *B = &w->b[i];
        double wt = B->mass * glen(B);
        double r = fmax(hypot(s->v[3 * i], s->v[3 * i + 1]) / wt,
                        fabs(s->v[3 * i + 2]) / (wt * fmax(B->rho, B->bound)));
        worst = fmax(worst, r);
    }
    return worst;
}

/* The candidate forces of the certificate's contacts c[0..nc) from the tick's solve
 * (s->c[0..ntick), impulses over h), matched by (a, b, feature); 1 when every contact found
 * one inside its cone. */
static int tick_forces(const struct solver *s, cp *c, int nc, int ntick)
{
    if (!(s->h > 0) || ntick == 0)
        return 0;
    for (int k = 0; k < nc; k++) {
        int found = 0;
        for (int q = 0; q < ntick && !found; q++) {
            const cp *t = &s->c[q];
            if (t->a == c[k].a && t->b == c[k].b && t->key == c[k].key) {
                c[k].ln = t->ln / s->h;
                c[k].lt = fmax(-c[k].mu * c[k].ln, fmin(c[k].mu * c[k].ln, t->lt / s->h));
                found = 1;
            }
        }
        if (!found)
            c[k].ln = c[k].lt = 0.0;
    }
    return 1;
}

/* A certificate for the bodies[0..nb) (all dynamic, with gravity): non-negative normal forces
 * inside the friction cones of their contacts (gap within cert_gap, against each other and
 * against static or asleep bodies) balancing every body's weight and torque. Returns the worst
 * relative residual (<= CERT_RESIDUAL: certified), INFINITY when a moving body touches them. */
static double certify(m2c_world *w, const int *bodies, int nb, int iterations)
{
    struct solver *s = w->solver;
    int keep_nc = s->nc;      /* the tick's contacts stay below: work above them */
    for (int m = 0; m < nb; m++)
        s->mark[bodies[m]] = 1;
    double gap = cert_gap(w);
    gen_ctx g = {w, gap, 1, 0};
    for (int m = 0; m < nb; m++)
        grid_neighbours(w, bodies[m], gen_visit, &g);
    cp *c = s->c + keep_nc;
    int nc = s->nc - keep_nc;
    double result = INFINITY;
    if (!g.fail) {
        for (int k = 0; k < nc; k++) {
            c[k].free_b = w->b[c[k].b].kind == M2C_DYNAMIC && s->mark[c[k].b];
            c[k].ln = c[k].lt = 0.0;
            c[k].bias = 0.0;
            c[k].vb[0] = c[k].vb[1] = 0.0;
            /* recompute the effective masses for this body set */
            const body *A = &w->b[c[k].a], *B = &w->b[c[k].b];
            double imb = c[k].free_b ? B->inv_mass : 0.0, iib = c[k].free_b ? B->inv_inertia : 0.0;
            double t[2] = {-c[k].n[1], c[k].n[0]};
            double rna = cross(c[k].ra, c[k].n), rnb = cross(c[k].rb, c[k].n);
            double rta = cross(c[k].ra, t), rtb = cross(c[k].rb, t);
            double kn = A->inv_mass + imb + A->inv_inertia * rna * rna + iib * rnb * rnb;
            double kt = A->inv_mass + imb + A->inv_inertia * rta * rta + iib * rtb * rtb;
            c[k].mn = kn > 0 ? 1 / kn : 0;
            c[k].mt = kt > 0 ? 1 / kt : 0;
        }
        /* first the forces of the tick's own solve (impulse / h of the same contact): a
         * converged pile's are an equilibrium, checked here like any other candidate; then
         * without friction (normal forces alone that balance are a certificate for any
         * friction: zero tangential force lies in every cone; a tall stack's static problem
         * converges much faster so), then with it */
        if (tick_forces(s, c, nc, keep_nc))
            result = residual(w, c, nc, bodies, nb);
        for (int friction = 0; friction < 2 && !(result <= CERT_RESIDUAL); friction++) {
            for (int k = 0; k < nc; k++)
                c[k].ln = c[k].lt = 0.0;
            for (int it = 0; it < iterations; it += 20) {
                for (int m = 0; m < nb; m++) {  /* the static problem: "velocity" = M^-1 force */
                    int i = bodies[m];
                    s->v[3 * i] = w->b[i].gx;
                    s->v[3 * i + 1] = w->b[i].gy;
                    s->v[3 * i + 2] = 0.0;
                }
                for (int k = 0; k < nc; k++)
                    apply(s, w, &c[k], c[k].ln, c[k].lt);
                for (int r = 0; r < 20; r++)
                    sweep(s, w, c, nc, friction, CERT_OMEGA);
                result = residual(w, c, nc, bodies, nb);
                if (result <= CERT_RESIDUAL)
                    break;
            }
        }
    }
    s->nc = keep_nc;
    for (int m = 0; m < nb; m++)
        s->mark[bodies[m]] = 0;
    return result;
}

/* Grow members[0..nb) by every body that `joins` and touches a member (a contact within
 * `gap`), transitively; returns the new count. The members are the queue. */
typedef int (*joins_fn)(const m2c_world *w, int j);

typedef struct {
    int *members, count;
    double gap;
    joins_fn joins;
} flood_ctx;

static void flood_visit(m2c_world *w, int i, int j, void *ctx)
{
    flood_ctx *f = ctx;
    struct solver *s = w->solver;
    if (s->mark[j] || !f->joins(w, j))
        return;
    const body *A = &w->b[i], *B = &w->b[j];
    if (centred_circle(w, A) && centred_circle(w, B)) {
        /* two circles about their centres: gen_parts' tests (its bounding circles', then
         * vertex against vertex: the only contact two circles have), without building the
         * contact (gen_pair here was 18% of a 2,000-disc pile's time: the wedge rule floods
         * about 300 bodies at a time) */
        snap sa = motion_at(&A->m, w->now), sb = motion_at(&B->m, w->now);
        double R = A->radius + B->radius, d[2] = {sb.x - sa.x, sb.y - sa.y};
        double d2 = d[0] * d[0] + d[1] * d[1], reach = A->bound + B->bound + f->gap, dist;
        if ((B->kind == M2C_DYNAMIC && d2 > reach * reach) || !vertices_within(d2, R, f->gap, &dist))
            return;
        s->mark[j] = 1;
        f->members[f->count++] = j;
        return;
    }
    int before = s->nc;
    gen_pair(w, i, j, f->gap);
    if (s->nc > before) {
        s->mark[j] = 1;
        f->members[f->count++] = j;
    }
    s->nc = before;
}

static int flood(m2c_world *w, int *members, int nb, double gap, joins_fn joins)
{
    struct solver *s = w->solver;
    flood_ctx f = {members, nb, gap, joins};
    for (int m = 0; m < nb; m++)
        s->mark[members[m]] = 1;
    for (int m = 0; m < f.count; m++)
        grid_neighbours(w, members[m], flood_visit, &f);
    for (int m = 0; m < f.count; m++)
        s->mark[members[m]] = 0;
    return f.count;
}

static int asleep_dynamic(const m2c_world *w, int j)
{
    return w->b[j].kind == M2C_DYNAMIC && w->b[j].state == ASLEEP;
}

/* The certificate of asleep body i's island (the asleep bodies touching it, transitively):
 * 1 or 0 and the residual (see certify); -1 for a body that is not asleep. */
int m2c_world_certificate(m2c_world *w, int i, double *res)
{
    if (i < 0 || i >= w->n || w->b[i].kind != M2C_DYNAMIC || w->b[i].state != ASLEEP)
        return -1;
    if (ensure(w) != 0)
        return -1;
    int *members = w->members;
    members[0] = i;
    int nb = flood(w, members, 1, cert_gap(w), asleep_dynamic);
    double r = certify(w, members, nb, CHECK_ITERATIONS);
    if (res)
        *res = r;
    return r <= CERT_RESIDUAL ? 1 : 0;
}

/* Is body k at rest now: asleep, or awake (not in the solver) with no point of it moving farther
 * than the tolerance before the solver's next tick would come (surface speed <= tolerance / h)?
 * A body put down at rest is exactly so. */
static int at_rest(const m2c_world *w, int k)
{
    const body *B = &w->b[k];
    if (B->kind != M2C_DYNAMIC)
        return 0;
    if (B->state == ASLEEP)
        return 1;
    if (B->state != AWAKE)
        return 0;
    snap sn = motion_at(&B->m, w->now);
    double v[3] = {sn.vx, sn.vy, sn.w};
    return surface_speed(B, v) * solver_step(w) <= w->cfg.tolerance;
}

typedef struct {
    double gap;
    int moves;               /* a member touches a moving kinematic body */
} mover_ctx;

static void mover_visit(m2c_world *w, int i, int j, void *ctx)
{
    mover_ctx *mc = ctx;
    const body *J = &w->b[j];
    if (mc->moves || J->kind != M2C_KINEMATIC || (J->m.vx == 0 && J->m.vy == 0 && J->m.w == 0))
        return;
    if (J->group >= 0 && J->group == w->b[i].group)
        return;
    struct solver *s = w->solver;
    int before = s->nc;
    gen_pair(w, i, j, mc->gap);
    mc->moves = s->nc > before;
    s->nc = before;
}

/* A soft contact of i with j where both are at rest: the bodies at rest touching them,
 * transitively (the asleep ones they lean on too), sleep at once when a certificate holds them
 * (certify). Staying at rest is then a motion of the contact problem: nothing to solve, and
 * the calm time (SLEEP_TIME, for bodies slowing down in the solver) has nothing to wait for.
 * Without this a column of boxes put down exactly touching entered the solver with a hop
 * (the soft contacts part each pair at |g| h / 2) and a sway (the local solves' sequential
 * corners), ran the tick's solve for 0.25 s and slept 5.6e-6 m from where it was put.
 * Returns the number of bodies put to sleep (0: none, the contact goes on as before). */
int solver_rest_at_once(m2c_world *w, int i, int j)
{
    if (!(solver_step(w) > 0) || !at_rest(w, i) || (w->b[j].kind == M2C_DYNAMIC && !at_rest(w, j))
        || ensure(w) != 0)
        return 0;
    struct solver *s = w->solver;
    int *members = w->members, nb = 0;
    members[nb++] = i;
    if (w->b[j].kind == M2C_DYNAMIC)
        members[nb++] = j;
    nb = flood(w, members, nb, cert_gap(w), at_rest);
    mover_ctx mc = {cert_gap(w), 0};
    for (int m = 0; m < nb && !mc.moves; m++)
        grid_neighbours(w, members[m], mover_visit, &mc);
    if (mc.moves || !(certify(w, members, nb, CERT_ITERATIONS) <= CERT_RESIDUAL))
        return 0;
    (void)s;
    w->st.certificates++;
    int slept = 0;
    for (int m = 0; m < nb; m++) {
        int k = members[m];
        if (w->b[k].state == ASLEEP)
            continue;
        m2c_event e = {w->now, M2C_EVENT_REST, k, -1, 0, 0, 0, 0, 0, 0};
        world_emit(w, &e);
        fall_asleep(w, k);
        slept++;
    }
    return slept;
}

/* -------------------------------------------------------------------------------------------
 * The tick.
 */

/* The island members[0..nb) with every asleep body touching it, transitively (within the
 * certificate's gap): a sleeper under a new load must hold it too, or it is no support.
 * Returns the new count. */
static int add_sleepers(m2c_world *w, int *members, int nb)
{
    return flood(w, members, nb, cert_gap(w), asleep_dynamic);
}

static void island_sleep(m2c_world *w, int root, const int *bodies, int nb)
{
    (void)root;
    for (int m = 0; m < nb; m++) {
        int k = bodies[m];
        struct solver *s = w->solver;
        int at = s->slot[k];
        s->list[at] = s->list[--s->n];
        s->slot[s->list[at]] = at;
        s->slot[k] = -1;
        m2c_event e = {w->now, M2C_EVENT_REST, k, -1, 0, 0, 0, 0, 0, 0};
        world_emit(w, &e);
        w->b[k].state = AWAKE;
        fall_asleep(w, k);
        w->b[k].m.ax = w->b[k].m.ay = 0.0;
    }
}

/* How much faster than its chord a contact must open now so that the free flights do not dip
 * into it before the next tick, H away: the gap's acceleration a_n from the motions (gravity)
 * bends the path below its chord by a_n tau (H - tau) / 2 where a_n > 0 (a body under a static
 * overhang or a kinematic body pressing from above: with the mean velocity alone it sank in and
 * met it again at once, at the slop's depth: 'stuck'). Starting apart at least at 0 keeps the
 * path above its tangent, so above the chord's end too. */
static double dip_bias(const m2c_world *w, const cp *c, double H)
{
    const body *A = &w->b[c->a], *B = &w->b[c->b];
    double an = (B->m.ax - A->m.ax) * c->n[0] + (B->m.ay - A->m.ay) * c->n[1];
    return an > 0 ? 0.5 * an * H : 0.0;
}

void solver_tick(m2c_world *w)
{
    struct solver *s = w->solver;
    double h = solver_step(w);
    s->h = h;
    w->st.solver_ticks++;
    /* gravity, then the contacts' impulses */
    for (int m = 0; m < s->n; m++) {
        int i = s->list[m];
        body *B = &w->b[i];
        body_commit(B, w->now);
        /* the last tick's push-out off again, unless an event changed the motion since; the
         * solve works on the mean velocity over the coming tick (semi-implicit Euler's v + g h):
         * v + (g - a / 2) h after a flight of acceleration a (gravity, since the last tick) */
        const double *vp = &s->vp[3 * i];
        int kept = s->pc[i] == B->counter;
        s->v[3 * i] = B->m.vx - (kept ? vp[0] : 0.0) + (B->gx - 0.5 * B->m.ax) * h;
        s->v[3 * i + 1] = B->m.vy - (kept ? vp[1] : 0.0) + (B->gy - 0.5 * B->m.ay) * h;
        s->v[3 * i + 2] = B->m.w - (kept ? vp[2] : 0.0);
    }
    remember(s);
    double slop = 10 * w->cfg.tolerance;
    gen_ctx g = {w, 4 * solver_slop(w), 0, 0};
    int n0 = s->n;
    for (int m = 0; m < n0; m++)
        grid_neighbours(w, s->list[m], gen_visit, &g);
    double scale = 0.0;
    for (int k = 0; k < s->nc; k++) {
        cp *q = &s->c[k];
        q->bias = (q->gap > slop ? -(q->gap - slop) / h : 0.0) + dip_bias(w, q, h);
        q->push = q->gap > 0 ? -q->gap / h : -PUSH_OUT * q->gap / h;
        q->lp = 0.0;
        const cp *p = recall(s, q);
        if (p) {
            q->ln = p->ln;
            q->lt = fmax(-q->mu * q->ln, fmin(q->mu * q->ln, p->lt));
            apply(s, w, q, q->ln, q->lt);
        }
        scale = fmax(scale, w->b[q->a].mass * glen(&w->b[q->a]) * h);
    }
    int limit = s->nc > 0 ? WORK_BUDGET / s->nc : 0;
    limit = limit < MIN_ITERATIONS ? MIN_ITERATIONS : limit > MAX_ITERATIONS ? MAX_ITERATIONS : limit;
    /* over-relaxed (TICK_OMEGA) like the certificate: the fixed point is the same, reached in
     * fewer sweeps */
    w->st.solver_iterations += pgs(s, w, s->c, s->nc, limit, CONVERGED * scale, TICK_OMEGA);
    for (int m = 0; m < s->n; m++) {
        double *vp = &s->vp[3 * s->list[m]];
        vp[0] = vp[1] = vp[2] = 0.0;
    }
    /* the push-out to a millionth of a weight's impulse per tick: a position correction
     * needs no more (Box2D gives it a few sweeps). At the velocities' billionth it ran the
     * whole budget every tick in a dense pile, 14% of its time, and the 200-disc pile slept
     * later (bench/contact.py, seeds 1-3: at 5.0, 8.5, 6.75 s against 4.5, 5.5, 5.0 s) */
    for (int it = 0; it < limit; it++)
        if (push_sweep(s, w, s->c, s->nc) <= PUSH_CONVERGED * scale)
            break;
    /* islands; which bodies touch anything */
    for (int m = 0; m < s->n; m++) {
        int i = s->list[m];
        s->uf[i] = i;
        s->flag[i] = 0;   /* bit 1: touches; bit 2: supported; bit 4: touches a mover */
    }
    for (int k = 0; k < s->nc; k++) {
        const cp *q = &s->c[k];
        s->flag[q->a] |= 1;
        if (q->free_b) {
            s->flag[q->b] |= 1;
            int ra = find(s->uf, q->a), rb = find(s->uf, q->b);
            if (ra != rb)
                s->uf[ra < rb ? rb : ra] = ra < rb ? ra : rb;
        } else {
            const body *B = &w->b[q->b];
            int moving = B->kind == M2C_KINEMATIC ? (B->m.vx != 0 || B->m.vy != 0 || B->m.w != 0)
                                                  : (B->kind == M2C_DYNAMIC && B->state != ASLEEP);
            if (q->gap <= cert_gap(w))
                s->flag[q->a] |= moving ? 4 : 2;
        }
    }
    /* motion segments from the solved velocities */
    int released = 0;
    for (int m = 0; m < s->n; m++) {
        int i = s->list[m];
        body *B = &w->b[i];
        /* the motion until the next tick: a free flight whose chord is the solved mean
         * velocity -- the positions at the ticks are semi-implicit Euler's (Box2D's), and the
         * energy is constant in between (a straight segment with no gravity climbed at its
         * speed, gaining m |g| v h until the next tick took it back). A resting body hops:
         * it leaves at |g| h / 2 and lands again at the tick, |g| h^2 / 8 high at most */
        B->m.ax = B->gx;
        B->m.ay = B->gy;
        B->m.vx = s->v[3 * i] + s->vp[3 * i] - 0.5 * B->m.ax * h;
        B->m.vy = s->v[3 * i + 1] + s->vp[3 * i + 1] - 0.5 * B->m.ay * h;
        B->m.w = s->v[3 * i + 2] + s->vp[3 * i + 2];
        B->counter++;
        s->pc[i] = B->counter;
        s->idle[i] = (s->flag[i] & 1) ? 0 : s->idle[i] + 1;
        double sp = surface_speed(B, &s->v[3 * i]);
        s->calm[i] = sp <= sleep_speed(w, B) ? s->calm[i] + h : 0.0;
    }
    for (int m = 0; m < s->n;) {
        int i = s->list[m];
        if (s->idle[i] >= IDLE_TICKS) {
            release(w, i);
            w->woken[released++] = i;
            continue;
        }
        m++;
    }
    /* sleep: per island (root = its smallest id), every body calm long enough, supported,
     * nothing moving against it, and a certificate */
    int *members = w->members;
    for (int m = 0; m < s->n; m++) {
        int i = s->list[m];
        int r = find(s->uf, i);
        s->uf[i] = r;
    }
    for (int m = 0; m < s->n; m++) {
        int root = s->list[m];
        if (s->uf[root] != root)
            continue;
        /* gather this island (order of the list: deterministic) */
        int nb = 0, ok = 1, supported = 0;
        for (int q = 0; q < s->n; q++) {
            int k = s->list[q];
            if (s->uf[k] != root)
                continue;
            members[nb++] = k;
            if (s->calm[k] < SLEEP_TIME || (s->flag[k] & 4))
                ok = 0;
            if (s->flag[k] & 2)
                supported = 1;
        }
        if (!ok || !supported)
            continue;
        int all = add_sleepers(w, members, nb);
        double r = certify(w, members, all, CERT_ITERATIONS);
        if (r <= CERT_RESIDUAL) {
            w->st.certificates++;
            island_sleep(w, root, members, nb);
            m = -1; /* the list changed: start over (islands already asleep are gone) */
        } else {
            /* try again later, the later the larger the island: an attempt costs up to
             * 2 x CERT_ITERATIONS sweeps over its contacts (a frozen 200-disc pile that
             * cannot be held spent a fifth of its time here at one try per 0.125 s) */
            double wait = 0.5 * SLEEP_TIME * (1.0 + nb / (double)CERT_WAIT_BODIES);
            for (int q = 0; q < nb; q++)
                s->calm[members[q]] = SLEEP_TIME - wait;
            if (all > nb) { /* the sleepers it leans on cannot take the load: they move too */
                int extra[64], ne = 0;
                for (int q = nb; q < all && ne < 64; q++)
                    extra[ne++] = members[q];
                for (int q = 0; q < ne; q++) {
                    if (w->b[extra[q]].state != ASLEEP)
                        continue;
                    int woke = wake_island(w, extra[q], w->woken + released, w->cap - released);
                    for (int k = 0; k < woke; k++)
                        solver_adopt(w, w->woken[released + k]);
                }
            }
        }
    }
    /* the next tick first: the predictions below leave the touching pairs to it */
    s->t_next = s->n > 0 ? w->now + h : INFINITY;
    if (s->n > 0) { /* on the grid of multiples of h (deterministic, whatever the adoption) */
        double t = round(w->now / h) * h + h;
        s->t_next = t > w->now ? t : w->now + h;
    }
    for (int m = 0; m < s->n; m++)
        world_predict_solver(w, s->list[m]);
    for (int k = 0; k < released; k++)
        world_predict(w, w->woken[k]);
}

/* Stop body k and the solver bodies in contact with it, transitively (the tick's island), at
 * this instant: local solves between a floor and a stack whose tick solve has not converged
 * yet (a column of boxes from a cold start) push one body back and forth for ever; stopped,
 * the next tick solves the whole island again, warm started. Energy only falls. */
static void halt_island(m2c_world *w, int k)
{
    w->members[0] = k;
    int nb = flood(w, w->members, 1, 4 * 10 * w->cfg.tolerance, solver_has);
    double H = solver_next_tick(w) - w->now;
    if (!(H > 0 && H < INFINITY))
        H = 0.0;
    for (int m = 0; m < nb; m++) {
        int i = w->members[m];
        body *B = &w->b[i];
        body_commit(B, w->now);
        /* at rest: back where it is at the next tick where gravity is in its motion */
        B->m.vx = -0.5 * B->m.ax * H;
        B->m.vy = -0.5 * B->m.ay * H;
        B->m.w = 0.0;
        B->instant = 0;
        B->counter++;
    }
    /* every member's motion changed: a pair of two members is searched from one side only
     * (k's, the caller's, searches all its pairs). Predicting them again was half of a
     * 2,000-disc pile's time, about 300 bodies at a time, 17 times a tick */
    int *mark = w->solver->mark;
    for (int m = 0; m < nb; m++)
        mark[w->members[m]] = 1;
    for (int m = 0; m < nb; m++)
        if (w->members[m] != k)
            world_predict_marked(w, w->members[m], mark);
    for (int m = 0; m < nb; m++)
        mark[w->members[m]] = 0;
}

/* Is t the present instant, within the rounding of the time (collisions in a row at one
 * instant: the wedge rule's count, the soft contacts remembered through it)? */
static int same_instant(const m2c_world *w, double t)
{
    return w->now - t <= 64 * DBL_EPSILON * (1 + fabs(w->now));
}

/* After a soft contact of solver body k: pairwise impulses between contacts at a small angle
 * (a ball wedged between a floor and a corner just above it) converge only geometrically, at
 * one instant; after WEDGE_INSTANT of them in a row the body stops (the motion it loses is
 * lost to the wedge; energy only falls) and the next tick's solve takes over. */
#define WEDGE_INSTANT 16
void solver_wedged(m2c_world *w, int k)
{
    body *K = &w->b[k];
    K->instant = same_instant(w, K->last_contact) ? K->instant + 1 : 0;
    K->last_contact = w->now;
    if (K->instant < WEDGE_INSTANT)
        return;
    halt_island(w, k);
}

/* -------------------------------------------------------------------------------------------
 * A soft contact between ticks: every touching contact of the two bodies is solved at once
 * (no gravity: an instant), so that a box landing flat does not bounce between its two corners
 * at one instant; then the event's own pair parts at least at -accel h / 2.
 */

typedef struct {
    int i, j;
    double margin;
} local_ctx;

static void local_visit(m2c_world *w, int k, int j, void *ctx)
{
    local_ctx *l = ctx;
    if (k == l->j && j == l->i)
        return; /* the pair is generated from i's side */
    if (w->solver->mark[j] == 2)
        return; /* a member solved already: the pair is generated from its side */
    const body *J = &w->b[j];
    if (J->group >= 0 && J->group == w->b[k].group)
        return;
    if (J->kind == M2C_DYNAMIC && J->state != SOLVING && J->state != ASLEEP && j != l->i && j != l->j)
        return; /* a body in flight: exact events */
    gen_pair(w, k, j, l->margin);
}

static void set_partner(m2c_world *w, cp *c, int free_b)
{
    const body *A = &w->b[c->a], *B = &w->b[c->b];
    c->free_b = free_b;
    c->vb[0] = c->vb[1] = 0.0;
    if (!free_b && B->kind != M2C_STATIC && B->state != ASLEEP) {
        snap sb = motion_at(&B->m, w->now);
        point_velocity(&sb, c->rb, c->vb);
    }
    double imb = free_b ? B->inv_mass : 0.0, iib = free_b ? B->inv_inertia : 0.0;
    arms(w, c);
    double rna = c->ka[0], rnb = c->kb[0], rta = c->ka[1], rtb = c->kb[1];
    double kn = A->inv_mass + imb + A->inv_inertia * rna * rna + iib * rnb * rnb;
    double kt = A->inv_mass + imb + A->inv_inertia * rta * rta + iib * rtb * rtb;
    c->mn = kn > 0 ? 1 / kn : 0.0;
    c->mt = kt > 0 ? 1 / kt : 0.0;
}

/* Body k's velocity now as the mean velocity until the next tick, H away (the solves work on
 * those: the chord the body's free flight follows until then), into s->v. */
static void load_mean(m2c_world *w, int k, double H)
{
    struct solver *s = w->solver;
    body *B = &w->b[k];
    body_commit(B, w->now);
    s->v[3 * k] = B->m.vx + 0.5 * B->m.ax * H;
    s->v[3 * k + 1] = B->m.vy + 0.5 * B->m.ay * H;
    s->v[3 * k + 2] = B->m.w;
}

/* ... and back: the motion whose chord until the next tick is the solved mean velocity. */
static void store_mean(m2c_world *w, int k, double H)
{
    struct solver *s = w->solver;
    body *B = &w->b[k];
    B->m.vx = s->v[3 * k] - 0.5 * B->m.ax * H;
    B->m.vy = s->v[3 * k + 1] - 0.5 * B->m.ay * H;
    B->m.w = s->v[3 * k + 2];
}

/* Remember soft contact (i, j) by the feature the prediction met, for the rest of this instant
 * (same_instant), in a ring of the last INSTANT_CONTACTS. Returns 1 when it
 * was met already at this instant: a pair that the solves part comes back. */
static int remember_instant(m2c_world *w, int i, int j, const event *ev)
{
    struct solver *s = w->solver;
    if (!same_instant(w, s->inst_t))
        s->ninst = s->next_inst = 0;
    s->inst_t = w->now;
    for (int m = 0; m < s->ninst; m++)
        if (s->inst[m].a == i && s->inst[m].b == j && s->inst[m].ev.feature == ev->feature
            && s->inst[m].ev.fa == ev->fa && s->inst[m].ev.fb == ev->fb
            && s->inst[m].ev.side == ev->side)
            return 1;
    int m = s->next_inst;
    s->next_inst = (m + 1) % INSTANT_CONTACTS;
    if (s->ninst < INSTANT_CONTACTS)
        s->ninst++;
    s->inst[m].a = i;
    s->inst[m].b = j;
    s->inst[m].ev = *ev;
    return 0;
}

/* Can remembered contact m join the local solve? Its first body is in it (mark) and its second
 * in it too or held (not a body in flight, nor a solver body beyond the solve's cap, nor one
 * removed since). */
static int instant_in_solve(const m2c_world *w, int m)
{
    const struct solver *s = w->solver;
    const body *B = &w->b[s->inst[m].b];
    return s->mark[s->inst[m].a] && B->kind != KIND_REMOVED
           && (B->kind != M2C_DYNAMIC || s->mark[s->inst[m].b] || B->state == ASLEEP);
}

/* A soft contact met again at one instant: every one met at this instant joins the local solve
 * as the prediction meets it (its feature's normal and point), with no friction, since the
 * solver's own contacts may meet the same two bodies by other features, and a solve with
 * friction may not meet them at all (solver_soft_response). Returns how many rows it added at
 * the end of the solver's contacts; a contact met for the first time at this instant adds
 * none (a pile's bodies meet several at one instant, and the solve parts them). */
static int add_instant_rows(m2c_world *w, int i, int j, const event *ev)
{
    struct solver *s = w->solver;
    int added = 0;
    if (!remember_instant(w, i, j, ev))
        return 0;
    /* (two round bodies, or one on a wall: one contact, the solver's own; a pile of discs
     * solves as before) */
    const body *B = &w->b[j];
    if (centred_circle(w, &w->b[i]) && (B->kind == M2C_STATIC || centred_circle(w, B)))
        return 0;
    for (int m = 0; m < s->ninst; m++)
        if (instant_in_solve(w, m)) {
            double n[2], p[2];
            contact_geometry(w, s->inst[m].a, s->inst[m].b, &s->inst[m].ev, n, p);
            int before = s->nc;
            add_one(w, s->inst[m].a, s->inst[m].b, n, p, 0.0, ~0u);
            if (s->nc > before) { /* (out of memory: the row is not there) */
                s->c[s->nc - 1].mu = 0.0;
                added++;
            }
        }
    return added;
}

int solver_soft_response(m2c_world *w, int i, int j, const event *ev, double closing, int pair_only,
                         m2c_event *out, int *moved, int cap, int *nmoved)
{
    *nmoved = 0;
    if (ensure(w) != 0)
        return -1;
    struct solver *s = w->solver;
    s->h = solver_step(w);
    /* the solve is the tick's, on the mean velocities until the next tick (gravity is in the
     * motions): a contact it leaves touching stays so at the tick, and the bodies fly in
     * between (a contact solved on the velocities now closed again at once under gravity: an
     * event at the slop's depth a millisecond later; with the mean, a box put down on a slope
     * no longer slid on until the tick) */
    double H = solver_next_tick(w) - w->now;
    if (!(H > 0 && H < INFINITY))
        H = s->h;
    int ids[2] = {i, j}, nid = w->b[j].kind == M2C_DYNAMIC ? 2 : 1;
    body *A = &w->b[i], *B = &w->b[j];
    snap sa = motion_at(&A->m, w->now);
    for (int m = 0; m < nid; m++)
        load_mean(w, ids[m], H);
    int keep = s->nc;
    local_ctx l = {i, j, 4 * 10 * w->cfg.tolerance};
    /* every solver body touching the pair, transitively (up to LOCAL_BODIES), is solved with
     * it: a neighbour held as a wall moving at its own velocity pushes energy into the pair
     * that nothing loses (measured: a 40-ball pile gained 0.019 J, a ball's kinetic energy
     * doubled, at one soft contact); neighbours solved one level deep passed a push along a
     * row of balls one contact per event, back and forth, against a kinematic ball pressing
     * it: 'stuck'. Beyond the cap, a wall moving at its velocity again.
     *
     * Two circles both in the solver already (pair_only) are solved alone: the ticks solve their
     * contacts with their neighbours, and what meets here is mostly that solve's residual (a
     * dense pile's slow mode, which no tick's budget meets), not a body arriving.
     * Two free bodies and no walls: an inelastic pairwise impulse, which keeps their momentum
     * and only loses energy; a neighbour it now closes on is an exact event of its own. A
     * 500-disc pile (bench/contact.py's scene, 5 s) had 45,000 soft contacts, 91% of them
     * between two solver bodies, each solved over 44 bodies and 65 contacts for 517 sweeps
     * (a fifth ran all 2,000): 37.3 s of CPU; pairwise 7.5 s, with 170,000 soft contacts. */
    for (int m = 0; m < nid; m++)
        s->mark[ids[m]] = 1;
    if (pair_only)
        gen_pair(w, i, j, l.margin);
    for (int m = 0; m < (pair_only ? 0 : nid + *nmoved); m++) {
        int k = m < nid ? ids[m] : moved[m - nid];
        int before = s->nc;
        grid_neighbours(w, k, local_visit, &l);
        s->mark[k] = 2;
        for (int q = before; q < s->nc; q++) {
            int b = s->c[q].b;
            if (s->mark[b] || !solver_has(w, b) || *nmoved >= cap || nid + *nmoved >= LOCAL_BODIES)
                continue;
            s->mark[b] = 1;
            moved[(*nmoved)++] = b;
            load_mean(w, b, H);
        }
    }
    int ninst = add_instant_rows(w, i, j, ev);
    cp *c = s->c + keep;
    int nc = s->nc - keep;
    for (int k = 0; k < nc; k++) {
        int b = c[k].b;
        set_partner(w, &c[k], w->b[b].kind == M2C_DYNAMIC && s->mark[b]);
        c[k].ln = c[k].lt = 0.0;
        c[k].bias = dip_bias(w, &c[k], H);
    }
    /* to the tick's own tolerance, a billionth of a weight's impulse per tick, within
     * MAX_ITERATIONS sweeps: an exact zero change was never reached in 3 of 4 soft contacts
     * of a dense 200-disc pile (2,000 sweeps each over up to 64 bodies: 35% of its time).
     * Stopping so at 50 sweeps (16ce350) jammed a box-and-disc pile into 'stuck'; at the cap
     * of 2,000 it settles (test_every_sleeper_of_a_pile_is_held). Over-relaxed as the
     * tick's solve (the same fixed point): the 200-disc pile's local solves, often 64 bodies,
     * met it in fewer sweeps */
    double scale = 0.0;
    for (int k = 0; k < nc; k++)
        scale = fmax(scale, w->b[c[k].a].mass * glen(&w->b[c[k].a]) * s->h);
    pgs(s, w, c, nc, MAX_ITERATIONS, CONVERGED * scale, TICK_OMEGA);
    /* ... then the contacts of this instant alone, with no friction, from where that solve
     * left the bodies: impulses that only part them. A triangle's corner pressed 1e-5 m into
     * a bin's corner (friction 0.64) met the floor's end by the floor's normal and the wall's
     * end by its own side's, at one point, 120 degrees apart: the solve with friction ran its
     * 2,000 sweeps, its impulses grew to 10 N s (a wedge that friction locks), and left the
     * floor's pair closing at 0.0095 m/s; each event's own parting then drove the other pair
     * in, 100,000 events at one instant ('stuck'), the wedge rule's stop no help. Without
     * friction the two meet their bound in a few sweeps (K is positive definite). */
    if (ninst) {
        cp *r = c + nc - ninst;
        for (int k = 0; k < ninst; k++)
            r[k].ln = 0.0;
        pgs(s, w, r, ninst, MAX_ITERATIONS, CONVERGED * scale, 1.0);
    }
    s->nc = keep;
    for (int m = 0; m < nid; m++)
        s->mark[ids[m]] = 0;
    for (int m = 0; m < *nmoved; m++) {
        s->mark[moved[m]] = 0;
        store_mean(w, moved[m], H);
        w->b[moved[m]].counter++;
    }
    /* the event's pair: parting at least as its gap's curvature beyond gravity's (a rotation
     * curving a corner into the other body) needs */
    double n[2], p[2];
    contact_geometry(w, i, j, ev, n, p);
    int fb = B->kind == M2C_DYNAMIC;
    cp q;
    memset(&q, 0, sizeof q);
    q.a = i;
    q.b = j;
    q.n[0] = n[0];
    q.n[1] = n[1];
    snap sb = motion_at(&B->m, w->now);
    q.ra[0] = p[0] - sa.x;
    q.ra[1] = p[1] - sa.y;
    q.rb[0] = p[0] - sb.x;
    q.rb[1] = p[1] - sb.y;
    set_partner(w, &q, fb);
    double u[2];
    rel_velocity(s, &q, u);
    double sep = u[0] * n[0] + u[1] * n[1];
    int moves = B->kind == M2C_DYNAMIC && B->state != ASLEEP;
    double ag = ((moves ? B->m.ax : 0.0) - A->m.ax) * n[0] + ((moves ? B->m.ay : 0.0) - A->m.ay) * n[1];
    double acc = contact_gap_accel(w, i, j, ev, NULL) - ag;
    double want = acc < 0 ? -0.5 * acc * s->h : 0.0;
    /* ... out of the pair's own energy (part_within_energy): no more than the solve left it
     * (in the centre-of-mass frame, or the wall's when b stands still) and the soft solve's
     * documented hop, m (|g| H / 2)^2 / 2 a body (docs/engine-contact.md). Without the hop the
     * cap also took the rounding-sized excess of slow contacts (2e-11 J of a box's 1.6e-5 J in
     * examples/scenes/pinball.toml), and that change of path led the box into 100,000 window
     * events at a guide's end: 'stuck' at t = 9.71 */
    int frame = fb || part_frame_still(B), parted = sep < want && q.mn > 0;
    double e_solved = 0.0;
    if (parted && frame) {
        for (int m = 0; m < nid; m++) {
            const body *K = &w->b[ids[m]];
            double g = glen(K) * H / 2;
            store_mean(w, ids[m], H);
            e_solved += K->mass * g * g / 2;
        }
        e_solved += pair_energy(w, A, B, fb);
    }
    if (parted)
        apply(s, w, &q, (want - sep) * q.mn, 0.0);
    for (int m = 0; m < nid; m++)
        store_mean(w, ids[m], H);
    if (parted && frame)
        part_within_energy(w, A, B, fb, n, q.ra, q.rb, e_solved);
    /* the impulse reported: the change of the pair's normal momentum at a's side */
    double dv = (A->m.vx - sa.vx) * n[0] + (A->m.vy - sa.vy) * n[1];
    *out = (m2c_event){w->now, M2C_EVENT_COLLISION, i, j, n[0], n[1], p[0], p[1], closing,
                       -dv * A->mass};
    return 0;
}
