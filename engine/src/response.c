/*
 * response.c -- what a contact does: an impulse along the contact normal, with restitution
 * and the angular terms of both bodies (static and kinematic bodies have infinite mass and
 * inertia).
 *
 * For bodies with inverse masses ma, mb, inverse inertias ia, ib, contact arms ra, rb (from
 * each reference point to the contact point) and the normal n from a to b, the closing
 * velocity along n is  u = -(vb + wb x rb - va - wa x ra) . n  and the impulse is
 *     J = (1 + e) u / (ma + mb + ia (ra x n)^2 + ib (rb x n)^2)
 * applied as -J n to a and +J n to b: momentum is conserved exactly, and for e = 1 so is the
 * kinetic energy (up to rounding). e is the product of the two bodies' restitutions.
 * With friction (sqrt of the two bodies' coefficients) a tangential impulse follows: see
 * friction_impulse.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "engine.h"

static double cross(const double a[2], const double b[2])
{
    return a[0] * b[1] - a[1] * b[0];
}

/* Contact point and normal (from body i towards body j) of the event's feature at now. */
void contact_geometry(const m2c_world *w, int i, int j, const event *ev, double n[2], double p[2])
{
    const body *A = &w->b[i], *B = &w->b[j];
    snap a = motion_at(&A->m, w->now), b = motion_at(&B->m, w->now);
    double P[2], Q[2], D[2];
    if (ev->feature == F_PP) {
        world_point(&a, &w->verts[2 * (A->vert + ev->fa)], P);
        world_point(&b, &w->verts[2 * (B->vert + ev->fb)], Q);
        double dx = Q[0] - P[0], dy = Q[1] - P[1], d = hypot(dx, dy);
        if (d > 0) {
            n[0] = dx / d;
            n[1] = dy / d;
        } else { /* coincident centres: along the relative velocity */
            double ux = a.vx - b.vx, uy = a.vy - b.vy, u = hypot(ux, uy);
            n[0] = u > 0 ? ux / u : 1.0;
            n[1] = u > 0 ? uy / u : 0.0;
        }
        double ra = vertex_radius(w, A, ev->fa);
        p[0] = P[0] + n[0] * ra;
        p[1] = P[1] + n[1] * ra;
        return;
    }
    /* a point of one body on an edge of the other: the edge's normal on the point's side */
    const body *E = ev->feature == F_PL ? B : A, *V = ev->feature == F_PL ? A : B;
    const snap *se = ev->feature == F_PL ? &b : &a, *sv = ev->feature == F_PL ? &a : &b;
    int edge = ev->feature == F_PL ? ev->fb : ev->fa, vert = ev->feature == F_PL ? ev->fa : ev->fb;
    world_point(sv, &w->verts[2 * (V->vert + vert)], P);
    world_vector(se, &w->edges[3 * (E->vert + edge)], D);
    double nl[2] = {ev->side * D[1], -ev->side * D[0]}; /* from the edge towards the point */
    double rv = vertex_radius(w, V, vert);
    p[0] = P[0] - nl[0] * rv;
    p[1] = P[1] - nl[1] * rv;
    if (ev->feature == F_PL) {
        n[0] = -nl[0];
        n[1] = -nl[1];
    } else {
        n[0] = nl[0];
        n[1] = nl[1];
    }
}

/* The contact as a reported event before any response (kind left to the caller): normal from
 * i to j, point, closing speed along the normal. */
void contact_event(const m2c_world *w, int i, int j, const event *ev, int kind, m2c_event *out)
{
    double n[2], p[2];
    contact_geometry(w, i, j, ev, n, p);
    snap a = motion_at(&w->b[i].m, w->now), b = motion_at(&w->b[j].m, w->now);
    double ra[2] = {p[0] - a.x, p[1] - a.y}, rb[2] = {p[0] - b.x, p[1] - b.y};
    double va[2] = {a.vx - a.w * ra[1], a.vy + a.w * ra[0]};
    double vb[2] = {b.vx - b.w * rb[1], b.vy + b.w * rb[0]};
    double closing = -((vb[0] - va[0]) * n[0] + (vb[1] - va[1]) * n[1]);
    *out = (m2c_event){w->now, kind, i, j, n[0], n[1], p[0], p[1], closing, 0.0};
}

/* Moving under the impulses: dynamic, neither asleep nor stopped to fall asleep. */
static int dynamic_awake(const body *b)
{
    return b->kind == M2C_DYNAMIC && !body_still(b);
}

/* Does B stand still for a pair's energy (static, asleep or stopped, or kinematic at rest)?
 * Then a contact with it can do no work. */
int part_frame_still(const body *B)
{
    return B->kind == M2C_STATIC || body_still(B)
           || (B->kind == M2C_KINEMATIC && B->m.vx == 0.0 && B->m.vy == 0.0 && B->m.ax == 0.0
               && B->m.ay == 0.0 && B->m.w == 0.0);
}

/* The pair's generalized velocity (A's, and B's if free_b) in its frame: the centre of mass's
 * when B moves under the impulses (free_b), else B's (it stands still); im: the inverse masses
 * and inertias (0: a degree of freedom no impulse changes). */
static void pair_frame(const m2c_world *w, const body *A, const body *B, int free_b, double q[6],
                       double im[6], double vc[2])
{
    vc[0] = vc[1] = 0.0;
    if (free_b) {
        double mt = A->mass + B->mass;
        vc[0] = (A->mass * A->m.vx + B->mass * B->m.vx) / mt;
        vc[1] = (A->mass * A->m.vy + B->mass * B->m.vy) / mt;
    }
    q[0] = A->m.vx - vc[0];
    q[1] = A->m.vy - vc[1];
    q[2] = A->m.w;
    q[3] = free_b ? B->m.vx - vc[0] : 0.0;
    q[4] = free_b ? B->m.vy - vc[1] : 0.0;
    q[5] = free_b ? B->m.w : 0.0;
    im[0] = im[1] = A->inv_mass;
    /* (a circle about its reference point: no contact turns it, none takes its spin) */
    im[2] = centred_circle(w, A) ? 0.0 : A->inv_inertia;
    im[3] = im[4] = free_b ? B->inv_mass : 0.0;
    im[5] = free_b && !centred_circle(w, B) ? B->inv_inertia : 0.0;
}

/* The pair's kinetic energy in its frame (pair_frame), of the motions the impulses change. */
double pair_energy(const m2c_world *w, const body *A, const body *B, int free_b)
{
    double q[6], im[6], vc[2], e = 0.0;
    pair_frame(w, A, B, free_b, q, im, vc);
    for (int d = 0; d < 6; d++)
        if (im[d] > 0)
            e += 0.5 * q[d] * q[d] / im[d];
    return e;
}

/* A minimum parting speed (the rest rule's a_n t_c / 2, the solver's -acc h / 2: the gap's
 * curvature) must not add energy: a static wall does no work, and a pair parting pushes each
 * other as much as it pushes back (issue 33: a compound spinning at 2,250 rad/s against a
 * thin wall's end went 53,367 J -> 196,948 J at one contact). When the pair's kinetic energy
 * in its frame (pair_frame) is above `target`, the excess is taken from the motion that does
 * not move the contact along its normal n (the part of the generalized velocity orthogonal,
 * in the mass metric, to the impulse's direction M^-1 c), scaled down: the parting speed is
 * kept. When the parting alone needs more than `target` (k: the normal speed per unit
 * impulse, it costs sep^2 / (2 k)), the pair parts at the speed `target` pays for and keeps
 * nothing else. Momentum is kept (the frame's). Returns 1 when the motion changed. */
int part_within_energy(const m2c_world *w, body *A, body *B, int free_b, const double n[2],
                       const double ra[2], const double rb[2], double target)
{
    double q[6], im[6], vc[2];
    pair_frame(w, A, B, free_b, q, im, vc);
    double c[6] = {-n[0], -n[1], -cross(ra, n), n[0], n[1], cross(rb, n)};
    double e = 0.0, k = 0.0, sep = 0.0;
    for (int d = 0; d < 6; d++)
        if (im[d] > 0) {
            e += 0.5 * q[d] * q[d] / im[d];
            k += c[d] * c[d] * im[d];
            sep += c[d] * q[d];
        }
    if (!(e > target) || !(k > 0) || !isfinite(e))
        return 0;
    target = fmax(target, 0.0);
    double en = 0.5 * sep * sep / k, alpha = sep / k, beta = 0.0;
    if (en <= target) /* en <= e (Cauchy-Schwarz): e - en > 0 here */
        beta = sqrt((target - en) / fmax(e - en, DBL_MIN));
    else
        alpha = (sep < 0 ? -1.0 : 1.0) * sqrt(2 * target / k);
    for (int d = 0; d < 6; d++)
        if (im[d] > 0)
            q[d] = alpha * im[d] * c[d] + beta * (q[d] - sep / k * im[d] * c[d]);
    A->m.vx = q[0] + vc[0];
    A->m.vy = q[1] + vc[1];
    if (im[2] > 0)
        A->m.w = q[2];
    if (free_b) {
        B->m.vx = q[3] + vc[0];
        B->m.vy = q[4] + vc[1];
        if (im[5] > 0)
            B->m.w = q[5];
    }
    return 1;
}

/* How body X's velocity changes per unit impulse along `push`: along push itself, or -- for a
 * body sliding on an edge (the rest rule) pushed into that edge -- along the edge only (the
 * edge takes the rest). Without it a ball sliding on the floor under another would bounce
 * between the two infinitely often at one instant. Returns 1 when constrained. */
static int response_direction(const body *X, const double push[2], double u[2])
{
    if (X->kind == M2C_DYNAMIC && X->state == RESTING && X->support_edge >= 0) {
        double ns = push[0] * X->support_n[0] + push[1] * X->support_n[1];
        if (ns < 0) {
            u[0] = push[0] - ns * X->support_n[0];
            u[1] = push[1] - ns * X->support_n[1];
            return 1;
        }
    }
    u[0] = push[0];
    u[1] = push[1];
    return 0;
}

/* Coulomb friction at an impact, after the normal impulse J: a tangential impulse that stops
 * the contact points' relative sliding if at most `bound` (= mu J) does (they stick), else
 * `bound` against the sliding. With t the tangent and rt = r x t, the sliding speed after the
 * normal impulse is vt = (vb - va).t + J (ia rna rta + ib rnb rtb) and a tangential impulse
 * P changes it by P kt, kt = ma + mb + ia rta^2 + ib rtb^2. The energy it takes,
 * -P (2 vt + P kt) / 2, is never negative for P between 0 and -vt / kt: friction never adds
 * energy. Through the arms a tangential impulse also changes the normal speed (by P knt,
 * knt = ia rna rta + ib rnb rtb): it is limited so that the bodies still part (the normal
 * speed `sep` after the normal impulse is not undone), else a spinning corner would strike
 * again at the same instant, again and again. Not applied to a body held by its edge (the
 * rest rule), which slides freely. */
static void friction_impulse(body *A, body *B, double bound, double sep, const double ra[2],
                             const double rb[2], const double va[2], const double vb[2],
                             const double n[2], double J, double rna, double rnb, double ima,
                             double imb, double iia, double iib)
{
    double t[2] = {-n[1], n[0]};
    double rta = cross(ra, t), rtb = cross(rb, t);
    double vt = (vb[0] - va[0]) * t[0] + (vb[1] - va[1]) * t[1] + J * (iia * rna * rta + iib * rnb * rtb);
    double kt = ima + imb + iia * rta * rta + iib * rtb * rtb;
    double knt = iia * rna * rta + iib * rnb * rtb;
    if (!(kt > 0) || vt == 0.0)
        return;
    double P = -vt / kt;
    if (P > bound)
        P = bound;
    else if (P < -bound)
        P = -bound;
    double keep = sep > 0 ? sep * (1 - 1e-9) : 0.0; /* the parting speed friction may take */
    if (P * knt < -keep)
        P = -keep / knt;
    A->m.vx -= P * t[0] * ima;
    A->m.vy -= P * t[1] * ima;
    A->m.w -= P * rta * iia;
    B->m.vx += P * t[0] * imb;
    B->m.vy += P * t[1] * imb;
    B->m.w += P * rtb * iib;
}

/* Does the contact of i with j join the contact solver (sustained contact, contact_solver.c)?
 * When it closes slower than v_soft and one side is held (static, kinematic, asleep, resting
 * or already in the solver), or both are in a burst. A ball on a static body is left to the
 * rest rule's bounce series (rest.c, rule 1), which ends it exactly (and hands it on when it
 * cannot simply lie there). */
static int soft_contact(m2c_world *w, int i, int j, const event *ev, double closing)
{
    const body *A = &w->b[i], *B = &w->b[j];
    double vs = solver_soft_speed(w, A);
    if (!(vs > 0) || closing > vs)
        return 0;
    /* ... or the two are in a burst (both touched something within t_c): a pair in free
     * space closing ever slower (e < 1 between a ball and a spinning box: a Zeno series of
     * 10^5 contacts within 1e-9 s) is sustained contact too */
    double tc = collapse_time(w);
    int burst = tc > 0 && w->now - A->last_contact < tc && w->now - B->last_contact < tc;
    int held = B->kind != M2C_DYNAMIC || B->state != AWAKE || A->state == SOLVING || burst;
    if (!held)
        return 0;
    if (A->state != SOLVING && A->nvert == 1 && B->kind == M2C_STATIC)
        return 0;
    /* ... and not where a shape turns more than a radian a tick and its rotation curves the
     * pair into each other faster than a soft contact closes: the soft response parts the
     * pair at the gap's curvature beyond gravity's times h / 2 (solver_soft_response), an
     * order-2 model that holds for a small turn only (a tumbling pile's bodies turn a tenth).
     * A triangle spinning at 15,700 rad/s in a Zeno burst against a ball (omega^2 r ~ 1.7e7
     * m/s^2) was sent off at 91,000 m/s (it had flown at 320) into the box's
     * corner 1.5e-5 m deep (issue 33, the long fuzz's seed 2, world 294). Such a contact is
     * an exact impact, parted by the rest rule over t_c, as without the solver. */
    double h = solver_step(w);
    double turn = h * fmax(A->nvert > 1 ? fabs(A->m.w) : 0.0, B->nvert > 1 ? fabs(B->m.w) : 0.0);
    if (!(turn > 1.0))
        return 1;
    int moves = B->kind == M2C_DYNAMIC && B->state != ASLEEP;
    double n[2], p[2];
    contact_geometry(w, i, j, ev, n, p);
    double ag = ((moves ? B->m.ax : 0.0) - A->m.ax) * n[0] + ((moves ? B->m.ay : 0.0) - A->m.ay) * n[1];
    double spin = contact_gap_accel(w, i, j, ev, NULL) - ag;
    return !(spin < 0 && -0.5 * spin * h > vs);
}

/* Returns the number of bodies woken (their ids in w->woken): the caller predicts them. */
int respond(m2c_world *w, int i, int j, const event *ev)
{
    body *A = &w->b[i], *B = &w->b[j];
    int woken = 0;
    body_commit(A, w->now);
    if (B->kind == M2C_DYNAMIC)
        body_commit(B, w->now);
    double n[2], p[2];
    contact_geometry(w, i, j, ev, n, p);
    snap a = motion_at(&A->m, w->now), b = motion_at(&B->m, w->now);
    double ra[2] = {p[0] - a.x, p[1] - a.y}, rb[2] = {p[0] - b.x, p[1] - b.y};
    double va[2] = {a.vx - a.w * ra[1], a.vy + a.w * ra[0]};
    double vb[2] = {b.vx - b.w * rb[1], b.vy + b.w * rb[0]};
    double closing = -((vb[0] - va[0]) * n[0] + (vb[1] - va[1]) * n[1]);
    int soft = soft_contact(w, i, j, ev, closing);
    if (soft && solver_rest_at_once(w, i, j) > 0)
        return 0; /* at rest and held: asleep, nothing moves */
    if (body_still(B) && ((wake_speed(w, B) > 0 && closing > wake_speed(w, B)) || soft)) {
        woken = wake_island(w, j, w->woken, w->cap);
        if (solver_step(w) > 0) /* they were at rest in contact: the solver takes them */
            for (int k = 0; k < woken; k++)
                solver_adopt(w, w->woken[k]);
    }
    if (soft) { /* sustained contact: both go to the solver (rest.c's rules do not apply) */
        /* two circles both in the solver: their pair alone (solver_soft_response). Only
         * circles about their centres: one contact, no turn curving it; two shapes with
         * corners, solved alone, went 'stuck' at one instant in examples/scenes/pinball.toml
         * (t = 9.711, test_rotation.py::test_pinball_never_overlaps) once their parting came
         * out of the pair's own energy (a67369b) */
        int pair_only = A->state == SOLVING && B->kind == M2C_DYNAMIC && B->state == SOLVING
                        && centred_circle(w, A) && centred_circle(w, B);
        solver_adopt(w, i);
        if (B->kind == M2C_DYNAMIC)
            solver_adopt(w, j);
        m2c_event out;
        int moved = 0;
        if (solver_soft_response(w, i, j, ev, closing, pair_only, &out, w->woken + woken,
                                 w->cap - woken, &moved) == 0) {
            woken += moved; /* the caller predicts them again */
            A->counter++;
            if (B->kind == M2C_DYNAMIC)
                B->counter++;
            w->st.collisions++;
            world_emit(w, &out);
            solver_wedged(w, i);
            if (B->kind == M2C_DYNAMIC)
                solver_wedged(w, j);
            return woken;
        }
    }
    int awake_b = dynamic_awake(B);
    double push_a[2] = {-n[0], -n[1]}, ua[2], ub[2];
    int ca = response_direction(A, push_a, ua);
    int cb = awake_b && response_direction(B, n, ub);
    if (!cb) {
        ub[0] = n[0];
        ub[1] = n[1];
    }
    /* a body that was resting and is not held by its edge is free again */
    if (!ca)
        rest_restore(w, i);
    if (awake_b && !cb)
        rest_restore(w, j);
    /* the frame in which the pair's energy is measured (part_within_energy): none when B is
     * kinematic and moving (it may do work) */
    int frame = awake_b || part_frame_still(B);
    double e0 = frame && !ca && !cb ? pair_energy(w, A, B, awake_b) : NAN;
    double e = soft ? 0.0 : A->restitution * B->restitution;
    double tc = collapse_time(w);
    int fixed = !awake_b;
    int recent = tc > 0 && !fixed && w->now - A->last_contact < tc && w->now - B->last_contact < tc;
    if (recent && A->elastic && B->elastic)
        e = 1.0; /* the collapse rule (rest.c, rule 2) */
    double ima = A->inv_mass, imb = awake_b ? B->inv_mass : 0.0;
    double iia = ca ? 0.0 : A->inv_inertia, iib = (awake_b && !cb) ? B->inv_inertia : 0.0;
    /* 0 for a circle about its reference point, not cross(ra, n)'s rounding (centred_circle) */
    double rna = centred_circle(w, A) ? 0.0 : cross(ra, n);
    double rnb = centred_circle(w, B) ? 0.0 : cross(rb, n);
    /* the relative normal velocity gained per unit impulse */
    double k = ima * -(ua[0] * n[0] + ua[1] * n[1]) + imb * (ub[0] * n[0] + ub[1] * n[1])
               + iia * rna * rna + iib * rnb * rnb;
    double J = 0.0;
    if (closing > 0 && k > 1e-12 * (ima + imb)) {
        J = (1 + e) * closing / k;
    }
    /* pressed together with (almost) no approach speed -- a ball sliding on the floor under
     * one falling onto it: they part at least as fast as an elastic bounce of period t_c.
     * What presses is the gap's curvature: the relative acceleration along the normal, and
     * for a rotating body what its rotation adds (a spinning corner curves into a ball even
     * without gravity). Without the rotation's part the prediction reported the pressed
     * pair again at the same instant, no impulse parted it, and the step ended "stuck"
     * (tests/engine/test_snapshot.py). Rotation's pressing is parted only there, with no
     * approach (an impact's bounce parts the pair already) or in a burst, and against a fixed
     * body only where gravity does not press (the rest rule's case). What the curvature's
     * part adds comes out of the pair's own energy (part_within_energy, below). */
    double an = (b.ax - a.ax) * n[0] + (b.ay - a.ay) * n[1];
    int press = awake_b && an < 0;
    /* what gravity's part of a minimum parting may add: sep^2 / (2 k), sep = a_n t_c / 2 */
    double ag = an, allow = an < 0 && k > 0 ? 0.5 * (0.5 * an * tc) * (0.5 * an * tc) / k : 0.0;
    int parted = 0;
    /* ... or in a burst (16 contacts in a row, each within t_c of the last: rest.c, rule 2),
     * where the bounce may part the pair slower than the rotation curves it back: a capsule
     * pair at 587 rad/s bounced elastically (rule 2) at a closing speed of 8e-5 m/s every
     * 3.8e-10 s, 1.26 million events (test_nothing_tunnels_in_random_worlds, once
     * part_within_energy had changed its path) */
    int chatter = tc > 0 && w->now - A->last_contact < tc && A->burst >= BURST;
    /* (an approach within the rounding of the contact points' speeds is none: a triangle
     * spinning at 290 rad/s on a rail, held by the solver, met it again and again at one
     * instant closing at 6.7e-16 m/s, each impulse 8e-17 N s, until 'stuck': a drawn world in a
     * bin, tests/engine/test_stuck.py) */
    double noise = 1e-12 * (hypot(va[0], va[1]) + hypot(vb[0], vb[1]));
    if ((A->m.w != 0.0 || B->m.w != 0.0) && (!(closing > noise) || chatter)) {
        int rotates; /* (only rotation's part presses here: a spinning ball's centre adds none) */
        double curve = contact_gap_accel(w, i, j, ev, &rotates);
        if (rotates && curve < 0 && (awake_b || !(an < 0))) {
            an = fmin(an, curve);
            press = 1;
        }
    }
    if (soft && k > 1e-12 * (ima + imb)) { /* part fast enough not to meet again before a tick */
        double acc = contact_gap_accel(w, i, j, ev, NULL);
        double want = acc < 0 ? -0.5 * acc * solver_step(w) : 0.0;
        double sep = -closing + J * k;
        if (sep < want) {
            J += (want - sep) / k;
            parted = 1;
        }
        double hop = ag < 0 ? -0.5 * ag * solver_step(w) : 0.0;
        allow = fmax(allow, 0.5 * hop * hop / k);
    }
    if (!soft && press && tc > 0 && k > 1e-12 * (ima + imb)) {
        double want = -0.5 * an * tc;
        double sep = -closing + J * k;
        if (sep < want) {
            J += (want - sep) / k;
            parted = 1;
        }
    }
    if (!isfinite(J)) { /* a mass or speed beyond doubles (1e308 kg against a floor): nothing
                           is written (static bodies' 0 * inf would be NaN); the step fails */
        w->overflow = 1;
        snprintf(w->err, sizeof w->err,
                 "overflow: the impulse between bodies %d and %d at t = %.17g is beyond double "
                 "precision (a mass, speed or size too large for the arithmetic)", i, j, w->now);
        return woken;
    }
    if (J != 0.0) {
        A->m.vx += J * ua[0] * ima;
        A->m.vy += J * ua[1] * ima;
        A->m.w -= J * rna * iia;
        B->m.vx += J * ub[0] * imb;
        B->m.vy += J * ub[1] * imb;
        B->m.w += J * rnb * iib;
    }
    double mu = sqrt(A->friction * B->friction);
    if (mu > 0 && J > 0 && !ca && !cb && !soft)
        friction_impulse(A, B, mu * J, -closing + J * k, ra, rb, va, vb, n, J, rna, rnb, ima,
                         imb, iia, iib);
    /* the curvature's part of the parting comes out of the pair's own energy */
    if (parted && isfinite(e0))
        part_within_energy(w, A, B, awake_b, n, ra, rb, e0 + allow);
    A->counter++;
    if (awake_b)
        B->counter++;
    w->st.collisions++;
    m2c_event out = {w->now, M2C_EVENT_COLLISION, i, j, n[0], n[1], p[0], p[1], closing, J};
    world_emit(w, &out);
    if (soft) { /* sustained contact: both go to the solver (rest.c's rules do not apply) */
        solver_adopt(w, i);
        solver_wedged(w, i);
        if (B->kind == M2C_DYNAMIC) {
            solver_adopt(w, j);
            solver_wedged(w, j);
        }
        return woken;
    }
    if (solver_has(w, i) || solver_has(w, j)) { /* an impact on a solver body: exact, no rule */
        A->last_contact = w->now;
        return woken;
    }
    if (fixed)
        rest_after_contact(w, i, j, ev, 1, e);
    rest_burst(w, i);
    A->last_contact = w->now;
    if (awake_b) {
        rest_burst(w, j);
        B->last_contact = w->now;
    }
    return woken;
}
