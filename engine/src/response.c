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
 */
#include <math.h>

#include "engine.h"

static double cross(const double a[2], const double b[2])
{
    return a[0] * b[1] - a[1] * b[0];
}

/* Contact point and normal (from body i towards body j) of the event's feature at now. */
static void geometry(const m2c_world *w, int i, int j, const event *ev, double n[2], double p[2])
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
        p[0] = P[0] + n[0] * A->radius;
        p[1] = P[1] + n[1] * A->radius;
        return;
    }
    /* a point of one body on an edge of the other: the edge's normal on the point's side */
    const body *E = ev->feature == F_PL ? B : A, *V = ev->feature == F_PL ? A : B;
    const snap *se = ev->feature == F_PL ? &b : &a, *sv = ev->feature == F_PL ? &a : &b;
    int edge = ev->feature == F_PL ? ev->fb : ev->fa, vert = ev->feature == F_PL ? ev->fa : ev->fb;
    world_point(sv, &w->verts[2 * (V->vert + vert)], P);
    world_vector(se, &w->edges[3 * (E->vert + edge)], D);
    double nl[2] = {ev->side * D[1], -ev->side * D[0]}; /* from the edge towards the point */
    p[0] = P[0] - nl[0] * V->radius;
    p[1] = P[1] - nl[1] * V->radius;
    if (ev->feature == F_PL) {
        n[0] = -nl[0];
        n[1] = -nl[1];
    } else {
        n[0] = nl[0];
        n[1] = nl[1];
    }
}

void respond(m2c_world *w, int i, int j, const event *ev)
{
    body *A = &w->b[i], *B = &w->b[j];
    body_commit(A, w->now);
    if (B->kind == M2C_DYNAMIC)
        body_commit(B, w->now);
    double n[2], p[2];
    geometry(w, i, j, ev, n, p);
    snap a = motion_at(&A->m, w->now), b = motion_at(&B->m, w->now);
    double ra[2] = {p[0] - a.x, p[1] - a.y}, rb[2] = {p[0] - b.x, p[1] - b.y};
    double va[2] = {a.vx - a.w * ra[1], a.vy + a.w * ra[0]};
    double vb[2] = {b.vx - b.w * rb[1], b.vy + b.w * rb[0]};
    double closing = -((vb[0] - va[0]) * n[0] + (vb[1] - va[1]) * n[1]);
    double e = A->restitution * B->restitution;
    double J = 0.0;
    if (closing > 0) {
        double rna = cross(ra, n), rnb = cross(rb, n);
        double k = A->inv_mass + B->inv_mass + A->inv_inertia * rna * rna
                   + B->inv_inertia * rnb * rnb;
        J = (1 + e) * closing / k;
        A->m.vx -= J * n[0] * A->inv_mass;
        A->m.vy -= J * n[1] * A->inv_mass;
        A->m.w -= J * rna * A->inv_inertia;
        B->m.vx += J * n[0] * B->inv_mass;
        B->m.vy += J * n[1] * B->inv_mass;
        B->m.w += J * rnb * B->inv_inertia;
    }
    A->counter++;
    A->last_contact = w->now;
    if (B->kind == M2C_DYNAMIC) {
        B->counter++;
        B->last_contact = w->now;
    }
    w->st.collisions++;
    m2c_event out = {w->now, M2C_EVENT_COLLISION, i, j, n[0], n[1], p[0], p[1], closing, J};
    world_emit(w, &out);
}
