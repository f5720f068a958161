/*
 * rest.c -- where event-driven engines break: bodies coming to rest, and inelastic collapse.
 *
 * A ball bouncing on a floor with e < 1 bounces infinitely often before a finite time (the
 * bounce times form a geometric series), and a settling pile can do the same among its balls
 * (inelastic collapse). The rules, with g_n the part of a body's gravity pressing it onto a
 * support (a static body, or a body asleep) and u its normal speed after the impulse:
 *
 * 1. Rest. When u <= v_r (the rest speed, below), the remaining bounces are summed: they would
 *    end at t* = t + 2u / (g_n (1 - e)) (t* = t for e = 1), when the body is reported at rest
 *    (M2C_EVENT_REST at t*). From the contact on, the body's normal velocity is zero: it sits on
 *    the support (the skipped bounces were at most u^2 / (2 g_n) high). Then
 *      a. if the support is an asleep body and its remaining speed is at most v_s (rule 4: a
 *         slow ball landing on a settled pile stays, the "sleepy particles" of Bannerman et
 *         al.), or its remaining speed is at most v_r and the contact normals of its supports
 *         (static or asleep, within the contact slack) hold it against gravity (-g in their
 *         cone, within 1e-6 rad), it stops and falls asleep at t* (circles; polygons slide);
 *      b. else, on an edge of a static body, it slides along the edge with the tangential
 *         part of its gravity, until it reaches the edge's end (then it flies again) or
 *         something hits it;
 *      c. else (a corner, a round support: no flat place to rest) it hops: its normal speed
 *         becomes at least g_n t_c / 2, as after an elastic bounce of period t_c.
 * 2. Collapse: a body is in a burst when it has had 16 collisions in a row, each within t_c of
 *    the one before. In a burst whose cluster (the bodies touching it, transitively) rests on
 *    nothing, a contact between two bursting bodies is elastic (e = 1: the rule of Luding &
 *    McNamara 1998, held back until 16 contacts have dissipated what they can; a supported
 *    cluster is left to rule 4 instead, since elastic contacts between two supports would
 *    never end). Two dynamic bodies pressed together with (almost) no approach speed (their
 *    accelerations push them into each other: a ball sliding on the floor under one falling
 *    onto it) part at least as fast as an elastic bounce of period t_c (a_n t_c / 2); so
 *    does a spinning pair in a burst, approaching or not (response.c).
 *    A body sliding on an edge (rule 1b) and pushed into it by another moves only along the
 *    edge: the edge takes the normal part of the impulse. Contacts due at the same instant
 *    are taken fastest first.
 * 3. Sleep and wake: an asleep body is static for everything that touches it, until something
 *    hits it faster than 10 v_r; then it and every asleep body touching it (transitively)
 *    wake, and fall asleep again by rule 1 when they settle.
 * 4. Settling clusters: balls pressed together in a pile exchange ever smaller impulses, many
 *    at one instant (the pairwise responses of a resting contact network). When a body has had
 *    16 (32, 64, ...) collisions in a row, each within t_c of the one before, the cluster of
 *    bodies touching it (transitively) falls asleep if every one of them moves slower than
 *    v_s and the cluster rests on something static or asleep (else it is not at rest, and the
 *    rules above go on). v_s = max(10 v_r, sqrt(g r) / 10) (r: the body's bounding radius;
 *    10 rest_speed when that is given). Rule 1a uses v_s too for a body landing on an asleep
 *    one. Frictionless balls in a heap would otherwise flow for a long time in resting contact,
 *    which an event-driven engine can only follow as a storm of tiny contacts.
 * 5. Jams: a body with 64 (128, 256, ...) collisions in a row at one instant (within a few
 *    ulps: a pressing contact found again just after the last) is jammed
 *    between others: the pairwise impulses of a contact network converge only geometrically
 *    (or not at all), never in finitely many steps. Its cluster falls asleep if it rests on
 *    something static or asleep, whatever its speed (the motion it loses is lost to the
 *    jam); else the cluster's contacts become elastic (rule 2).
 * Parameters: t_c = collapse_time (default 1e-3 s; < 0: rules 2 and 4 off), v_r = rest_speed,
 * by default max(sqrt(2 g_n tolerance), g_n t_c) (< 0: rules 1, 3 and 4 off): below it a bounce
 * rises less than max(tolerance, g_n t_c^2 / 2). No rule adds energy except gravity's part of
 * the minimum parting speeds of 1c and 2 (at most m (g_n t_c / 2)^2 / 2 per pressing contact:
 * the curvature's part is taken out of the pair's own energy, response.c part_within_energy);
 * the others only remove motion.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "engine.h"

#define DEFAULT_COLLAPSE_TIME 1e-3
#define REST_ANGLE 1e-6
#define MAX_SUPPORTS 8

double collapse_time(const m2c_world *w)
{
    double tc = w->cfg.collapse_time;
    return tc < 0 ? 0.0 : tc > 0 ? tc : DEFAULT_COLLAPSE_TIME;
}

double rest_speed(const m2c_world *w, double gn)
{
    if (w->cfg.rest_speed < 0)
        return -1.0;
    if (w->cfg.rest_speed > 0)
        return w->cfg.rest_speed;
    return fmax(sqrt(2 * gn * w->cfg.tolerance), gn * collapse_time(w));
}

/* Rule 4's speed: a tenth of sqrt(g r), the speed a ball of radius r gains falling r/200. */
static double settle_speed(const m2c_world *w, const body *b)
{
    double gl = hypot(b->gx, b->gy);
    if (w->cfg.rest_speed > 0)
        return 10 * w->cfg.rest_speed;
    return fmax(10 * rest_speed(w, gl), 0.1 * sqrt(gl * b->bound));
}

double wake_speed(const m2c_world *w, const body *b)
{
    double v = rest_speed(w, hypot(b->gx, b->gy));
    return v > 0 ? 10 * v : 0.0;
}

/* Gap between circle K and one part J of a shape now, and the unit normal from J towards K. */
static double circle_part_gap(const m2c_world *w, const body *K, const body *J, double n[2])
{
    snap a = motion_at(&K->m, w->now), b = motion_at(&J->m, w->now);
    double c[2];
    world_point(&a, &w->verts[2 * K->vert], c);
    double best = INFINITY;
    n[0] = 0.0;
    n[1] = 1.0;
    int nedges = J->nvert >= 3 ? J->nvert : J->nvert - 1;
    for (int v = 0; v < J->nvert; v++) {
        double p[2];
        world_point(&b, &w->verts[2 * (J->vert + v)], p);
        double dx = c[0] - p[0], dy = c[1] - p[1], d = hypot(dx, dy);
        if (d < best && d > 0) {
            best = d;
            n[0] = dx / d;
            n[1] = dy / d;
        }
        if (v < nedges) {
            double u[2];
            const double *e = &w->edges[3 * (J->vert + v)];
            world_vector(&b, e, u);
            double along = dx * u[0] + dy * u[1];
            if (along > 0 && along < e[2]) {
                double across = dx * u[1] - dy * u[0];
                if (fabs(across) < best) {
                    best = fabs(across);
                    double s = across >= 0 ? 1.0 : -1.0;
                    n[0] = s * u[1];
                    n[1] = -s * u[0];
                }
            }
        }
    }
    return best - K->radius - J->radius;
}

/* Gap between circle k and body j's shape now (its nearest part), and the unit normal from j
 * towards k. */
static double circle_gap(const m2c_world *w, int k, int j, double n[2])
{
    const body *K = &w->b[k], *J = &w->b[j];
    if (J->nparts == 1)
        return circle_part_gap(w, K, J, n);
    double best = INFINITY;
    for (int p = 0; p < J->nparts; p++) {
        body v = part_view(w, J, p);
        double m[2], g = circle_part_gap(w, K, &v, m);
        if (g < best) {
            best = g;
            n[0] = m[0];
            n[1] = m[1];
        }
    }
    return best;
}

/* The velocity closest to v with no part into any support it approaches at most as fast as
 * vslow (v . n >= 0 for those normals): a perfectly inelastic response to all of them at once.
 * Without it a body wedged between two supports (a ball slid under an asleep one) would bounce
 * between them infinitely often at one instant. A support approached faster is an impact of
 * its own at this instant (its contact event follows), whatever the order: a ball going
 * exactly into a corner bounces off both walls and is not stopped by the second (issue 33:
 * e = 1 lost half its energy; with no gravity vslow = 0 and nothing is projected). Returns 1
 * when the velocity changed. */
static int project_velocity(body *K, const double (*nrm)[2], int count, double vslow)
{
    double v[2] = {K->m.vx, K->m.vy}, dv[MAX_SUPPORTS + 1];
    int inside = 1;
    for (int m = 0; m < count; m++) {
        dv[m] = v[0] * nrm[m][0] + v[1] * nrm[m][1];
        if (dv[m] < 0 && dv[m] >= -vslow)
            inside = 0;
    }
    if (inside)
        return 0;
    double best[2] = {0.0, 0.0}, dist = hypot(v[0], v[1]);
    for (int m = 0; m < count; m++) {
        double d = dv[m];
        if (d >= 0 || d < -vslow)
            continue;
        double p[2] = {v[0] - d * nrm[m][0], v[1] - d * nrm[m][1]};
        int ok = 1;
        for (int l = 0; l < count; l++)
            if (l != m && dv[l] >= -vslow
                && p[0] * nrm[l][0] + p[1] * nrm[l][1] < -1e-12 * hypot(p[0], p[1]))
                ok = 0;
        if (ok && -d < dist) {
            dist = -d;
            best[0] = p[0];
            best[1] = p[1];
        }
    }
    K->m.vx = best[0];
    K->m.vy = best[1];
    K->counter++;
    return 1;
}

/* Distance between two shapes (parts) now (touching ~ 0): the least distance of a vertex of
 * one to a vertex or edge of the other, minus the radii. */
static double part_gap(const m2c_world *w, const body *K, const body *J)
{
    const body *B[2] = {K, J};
    snap s[2] = {motion_at(&B[0]->m, w->now), motion_at(&B[1]->m, w->now)};
    double best = INFINITY;
    for (int side = 0; side < 2; side++) {
        const body *P = B[side], *E = B[1 - side];
        const snap *sp = &s[side], *se = &s[1 - side];
        int nedges = E->nvert >= 3 ? E->nvert : E->nvert - 1;
        for (int v = 0; v < P->nvert; v++) {
            double c[2];
            world_point(sp, &w->verts[2 * (P->vert + v)], c);
            for (int u = 0; u < E->nvert; u++) {
                double q[2];
                world_point(se, &w->verts[2 * (E->vert + u)], q);
                double d = hypot(c[0] - q[0], c[1] - q[1]);
                if (d < best)
                    best = d;
                if (u < nedges) {
                    double dir[2];
                    const double *e = &w->edges[3 * (E->vert + u)];
                    world_vector(se, e, dir);
                    double along = (c[0] - q[0]) * dir[0] + (c[1] - q[1]) * dir[1];
                    if (along > 0 && along < e[2]) {
                        double across = fabs((c[0] - q[0]) * dir[1] - (c[1] - q[1]) * dir[0]);
                        if (across < best)
                            best = across;
                    }
                }
            }
        }
    }
    return best - B[0]->radius - B[1]->radius;
}

/* Distance between the shapes of bodies k and j now: their nearest parts'. */
static double body_gap(const m2c_world *w, int k, int j)
{
    const body *K = &w->b[k], *J = &w->b[j];
    if (K->nparts == 1 && J->nparts == 1)
        return part_gap(w, K, J);
    double best = INFINITY;
    for (int p = 0; p < K->nparts; p++) {
        body u = part_view(w, K, p);
        for (int q = 0; q < J->nparts; q++) {
            body v = part_view(w, J, q);
            best = fmin(best, part_gap(w, &u, &v));
        }
    }
    return best;
}

/* Is the direction `up` in the cone of the normals? */
static int holds(const double (*nrm)[2], int count, const double up[2])
{
    double c = cos(REST_ANGLE);
    for (int a = 0; a < count; a++) {
        if (nrm[a][0] * up[0] + nrm[a][1] * up[1] >= c)
            return 1;
        for (int b = 0; b < count; b++) {
            double ca = nrm[a][0] * up[1] - nrm[a][1] * up[0];    /* a x up */
            double cb = up[0] * nrm[b][1] - up[1] * nrm[b][0];    /* up x b */
            double ab = nrm[a][0] * nrm[b][1] - nrm[a][1] * nrm[b][0];
            if (ca > 0 && cb > 0 && ab > 0)
                return 1;
        }
    }
    return 0;
}

typedef struct {
    int k, s, count;
    double slack;
    double (*nrm)[2];
} gather;

static void collect(m2c_world *w, int k, int j, void *ctx)
{
    gather *g = ctx;
    const body *J = &w->b[j];
    if (j == g->s || g->count >= MAX_SUPPORTS)
        return;
    if (!(J->kind == M2C_STATIC || body_still(J)))
        return;
    double n[2];
    if (circle_gap(w, k, j, n) <= g->slack) {
        g->nrm[g->count][0] = n[0];
        g->nrm[g->count][1] = n[1];
        g->count++;
    }
}

/* A sustained contact ends: body k leaves its support (M2C_FLAG_SEPARATE on either). */
static void report_separate(m2c_world *w, int k)
{
    const body *K = &w->b[k];
    int s = K->support;
    if (s < 0 || !((K->flags | w->b[s].flags) & M2C_FLAG_SEPARATE))
        return;
    m2c_event e = {w->now, M2C_EVENT_SEPARATE, k, s, 0, 0, 0, 0, 0, 0};
    world_emit(w, &e);
}

void rest_restore(m2c_world *w, int k)
{
    body *K = &w->b[k];
    if (K->state == AWAKE || K->state == SOLVING)
        return; /* (a solver body stays in the solver: its gravity is applied at the ticks) */
    body_commit(K, w->now);
    report_separate(w, k);
    K->state = AWAKE;
    K->m.ax = K->gx;
    K->m.ay = K->gy;
    K->support = -1;
    K->rest_time = NAN;
    K->counter++;
}

/* After the impulse of a contact between dynamic body k and its support s (static, or
 * asleep): the rest rule. Returns 1 when k's motion changed. */
int rest_after_contact(m2c_world *w, int k, int s, const event *ev, int k_is_a, double e)
{
    body *K = &w->b[k];
    const body *S = &w->b[s];
    if (!(S->kind == M2C_STATIC || body_still(S)))
        return 0; /* nothing rests on a moving body */
    double n[2], p[2];
    contact_geometry(w, k_is_a ? k : s, k_is_a ? s : k, ev, n, p);
    if (k_is_a) { /* the geometry's normal points from a to b: we want it from s to k */
        n[0] = -n[0];
        n[1] = -n[1];
    }
    double gl = hypot(K->gx, K->gy);
    double vmax = rest_speed(w, gl);
    if (vmax < 0 || K->nvert != 1)
        return 0;
    /* the supports it touches (this one first) hold it: no velocity into any of them */
    double nrm[MAX_SUPPORTS + 1][2];
    nrm[0][0] = n[0];
    nrm[0][1] = n[1];
    gather g = {k, s, 1, (gl > 0 ? 2 * vmax * vmax / gl : 0.0) + w->cfg.tolerance, nrm};
    grid_neighbours(w, k, collect, &g);
    int changed = project_velocity(K, (const double (*)[2])nrm, g.count, vmax);
    double gn = -(K->gx * n[0] + K->gy * n[1]);
    if (!(gn > 0))
        return changed; /* nothing presses it onto s there */
    double vr = rest_speed(w, gn);
    double u = K->m.vx * n[0] + K->m.vy * n[1];
    if (u > vr)
        return changed; /* a real bounce */
    double t_rest = w->now + (e < 1 ? 2 * fmax(u, 0.0) / (gn * (1 - e)) : 0.0);
    int flat = ev->feature == (k_is_a ? F_PL : F_LP) && w->b[s].kind == M2C_STATIC;
    double vt[2] = {K->m.vx - u * n[0], K->m.vy - u * n[1]};
    {
        double up[2] = {-K->gx / gl, -K->gy / gl};
        int on_asleep = S->kind == M2C_DYNAMIC;
        double vt_abs = hypot(vt[0], vt[1]);
        /* the contact point's own slip: a ball put down spinning on the spot slides on the
         * floor until friction rolls it (it was frozen, its spin dropped) */
        snap sk = motion_at(&K->m, w->now);
        double r[2] = {p[0] - sk.x, p[1] - sk.y};
        double slip[2] = {vt[0] - K->m.w * r[1], vt[1] + K->m.w * r[0]};
        double slip_t = fabs(slip[0] * n[1] - slip[1] * n[0]);
        int rubs = slip_t > vr && K->friction * S->friction > 0;
        int spins = fabs(K->m.w) * K->rho > vr;
        if (solver_step(w) > 0 && (on_asleep || rubs || spins || (vt_abs > vr && K->friction * S->friction > 0)))
            return solver_adopt(w, k) | changed; /* sustained contact: the solver decides */
        if ((on_asleep && vt_abs <= settle_speed(w, K))
            || (vt_abs <= vr && holds((const double (*)[2])nrm, g.count, up))) {
            K->m.vx = K->m.vy = K->m.w = 0.0;
            K->m.ax = K->m.ay = 0.0;
            K->state = RESTING;
            K->sleep_at_rest = 1;
            K->support = s;
            K->support_edge = -1;
            K->rest_time = t_rest;
            K->counter++;
            return 1;
        }
    }
    if (flat) {
        K->m.vx = vt[0];
        K->m.vy = vt[1];
        K->m.ax = K->gx + gn * n[0];  /* g minus its normal part */
        K->m.ay = K->gy + gn * n[1];
        K->state = RESTING;
        K->sleep_at_rest = 0;
        K->support = s;
        K->support_edge = k_is_a ? ev->fb : ev->fa;
        K->support_n[0] = n[0];
        K->support_n[1] = n[1];
        K->rest_time = t_rest;
        K->counter++;
        if (rest_leave_time(w, k, INFINITY) > 0)
            return 1;
        /* at the edge's end and leaving it: no sliding there (it would leave at once, land
         * on the end again at the same instant and loop); a corner, as below */
        rest_restore(w, k);
    }
    if (solver_step(w) > 0)
        return solver_adopt(w, k) | changed; /* a corner or a round support: the solver */
    double hop = 0.5 * gn * collapse_time(w);
    if (u < hop) {
        K->m.vx += (hop - u) * n[0];
        K->m.vy += (hop - u) * n[1];
        K->counter++;
        return 1;
    }
    return changed;
}

/* When a body sliding on an edge reaches one of its ends (INFINITY if not before tmax). */
double rest_leave_time(const m2c_world *w, int k, double tmax)
{
    const body *K = &w->b[k], *S = &w->b[K->support];
    if (K->support_edge < 0)
        return INFINITY;
    snap a = motion_at(&K->m, w->now), b = motion_at(&S->m, w->now);
    double L[2], D[2];
    world_point(&b, &w->verts[2 * (S->vert + K->support_edge)], L);
    world_vector(&b, &w->edges[3 * (S->vert + K->support_edge)], D);
    double len = w->edges[3 * (S->vert + K->support_edge) + 2];
    double x = (a.x - L[0]) * D[0] + (a.y - L[1]) * D[1];
    double v = a.vx * D[0] + a.vy * D[1], acc = a.ax * D[0] + a.ay * D[1];
    double t0 = first_crossing(x, v, acc, 0.0, -1, tmax);
    double t1 = first_crossing(x, v, acc, len, 1, tmax);
    return fmin(t0, t1);
}

typedef struct {
    m2c_world *w;
    int top, cap;
    double slack;
} flood;

/* Asleep, or about to be (stopped on its supports, rule 1a): what a wake wakes. */
int body_still(const body *b)
{
    return b->kind == M2C_DYNAMIC
           && (b->state == ASLEEP || (b->state == RESTING && b->sleep_at_rest));
}
#define still body_still

static void push_asleep(m2c_world *w, int k, int j, void *ctx)
{
    flood *f = ctx;
    body *J = &w->b[j];
    if (J->kind != M2C_DYNAMIC || !still(J) || f->top >= f->cap)
        return;
    if (body_gap(w, k, j) <= f->slack)
        w->stack[f->top++] = j;
}

/* Wake asleep body i and every asleep body touching it, transitively; their ids go to
 * woken[0..count) (room for every body: cap = w->cap). */
int wake_island(m2c_world *w, int i, int *woken, int cap)
{
    flood f = {w, 0, w->n, 0};
    int count = 0;
    w->stack[f.top++] = i;
    while (f.top > 0) {
        int k = w->stack[--f.top];
        body *K = &w->b[k];
        if (!still(K))
            continue;
        body_commit(K, w->now);
        report_separate(w, k);
        K->state = AWAKE;
        K->m.t = w->now;
        K->m.ax = K->gx;
        K->m.ay = K->gy;
        K->support = -1;
        K->rest_time = NAN;
        K->counter++;
        w->st.wakes++;
        if (count < cap)
            woken[count++] = k;
        m2c_event e = {w->now, M2C_EVENT_WAKE, k, -1, 0, 0, 0, 0, 0, 0};
        world_emit(w, &e);
        double vr = rest_speed(w, hypot(K->gx, K->gy));
        f.slack = (vr > 0 ? 2 * vr * vr / fmax(hypot(K->gx, K->gy), 1e-300) : 0) + w->cfg.tolerance;
        grid_neighbours(w, k, push_asleep, &f);
    }
    return count;
}

typedef struct {
    int top, cap, members, fast, supported;
    double slack, vmax;
} cluster;

static void cluster_visit(m2c_world *w, int k, int j, void *ctx)
{
    cluster *c = ctx;
    body *J = &w->b[j];
    int fixed = J->kind == M2C_STATIC || body_still(J) || J->state == SOLVING;
    if (J->kind == M2C_KINEMATIC)
        return;
    if (body_gap(w, k, j) > c->slack)
        return;
    if (fixed) {
        c->supported = 1;
        return;
    }
    if (J->burst >= 0 && c->top < c->cap) { /* not yet in the cluster (burst < 0 marks) */
        J->burst = -1 - J->burst;
        w->stack[c->top++] = j;
    }
}

static void repredict_awake(m2c_world *w, int k, int j, void *ctx)
{
    (void)k;
    (void)ctx;
    if (w->b[j].kind == M2C_DYNAMIC && w->b[j].state != ASLEEP)
        world_predict(w, j);  /* (a still body predicts too: it may yet be hit) */
}

/* Rules 4 and 5: after a collision of k. */
void rest_burst(m2c_world *w, int k)
{
    body *K = &w->b[k];
    double tc = collapse_time(w);
    K->burst = (tc > 0 && w->now - K->last_contact < tc) ? K->burst + 1 : 0;
    /* at one instant: the same time, or within a few ulps (a contact found again just after
     * the last one, the rounding of a pressing contact) */
    K->instant = w->now - K->last_contact <= 64 * DBL_EPSILON * (1 + fabs(w->now)) ? K->instant + 1 : 0;
    if (K->burst == 0)
        K->elastic = 0;
    double gl = hypot(K->gx, K->gy);
    double vr = rest_speed(w, gl);
    int jammed = K->instant >= INSTANT && (K->instant & (K->instant - 1)) == 0;
    /* tried at 16, 32, 64, ... collisions into a burst: a flood per event would cost O(N) */
    if (!jammed && (K->burst < BURST || (K->burst & (K->burst - 1)) != 0))
        return;
    if (vr < 0 || !(gl > 0))
        return;
    double vmax = jammed ? INFINITY : settle_speed(w, K);
    cluster c = {0, w->cap, 0, 0, 0, 2 * vr * vr / gl + w->cfg.tolerance, vmax};
    /* flood the touching dynamic bodies, marking them (burst -> -1 - burst) */
    K->burst = -1 - K->burst;
    w->stack[c.top++] = k;
    int n = 0;
    while (c.top > 0) {
        int j = w->stack[--c.top];
        w->members[n++] = j;
        snap s = motion_at(&w->b[j].m, w->now);
        if (hypot(s.vx, s.vy) + fabs(s.w) * w->b[j].rho > vmax)
            c.fast = 1;
        grid_neighbours(w, j, cluster_visit, &c);
    }
    int freeze = !c.fast && c.supported;
    if (jammed && !c.supported)
        K->elastic = 1;
    for (int m = 0; m < n; m++) {
        body *J = &w->b[w->members[m]];
        J->burst = -1 - J->burst; /* unmark */
        J->elastic = !c.supported; /* rule 2: a burst in free space turns elastic */
    }
    if (freeze && solver_step(w) > 0) { /* the solver takes the cluster (it sleeps certified) */
        for (int m = 0; m < n; m++)
            solver_adopt(w, w->members[m]);
        return;
    }
    if (freeze)
        for (int m = 0; m < n; m++) {
            m2c_event e = {w->now, M2C_EVENT_REST, w->members[m], -1, 0, 0, 0, 0, 0, 0};
            world_emit(w, &e);
            fall_asleep(w, w->members[m]);
        }
}

void fall_asleep(m2c_world *w, int k)
{
    body *J = &w->b[k];
    body_commit(J, w->now);
    J->m.vx = J->m.vy = J->m.w = J->m.ax = J->m.ay = 0.0;
    J->state = ASLEEP;
    J->burst = J->instant = 0;
    J->rest_time = NAN;
    J->counter++;
    w->st.rests++;
    world_predict(w, k);
    /* an asleep body predicts nothing: its awake neighbours predict against its new (still)
     * motion, or a pair predicted only by this body would be lost */
    grid_neighbours(w, k, repredict_awake, NULL);
}
