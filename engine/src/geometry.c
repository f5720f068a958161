/* geometry.c -- shapes at one instant: gaps and overlaps between bodies (what set_pose checks
 * before it moves a body), and the collision filter. Prediction never uses these: it finds
 * contacts as roots of the contact polynomials (predict.c). */
#include <math.h>

#include "engine.h"

int pair_filtered(const body *a, const body *b)
{
    if (a->group >= 0 && a->group == b->group)
        return 0;
    return (a->category & b->mask) != 0 && (b->category & a->mask) != 0;
}

static int nedges(const body *b)
{
    return b->nvert >= 3 ? b->nvert : b->nvert - 1;
}

/* Distance from point c to segment q + s d, s in [0, len]. */
static double point_segment(const double c[2], const double q[2], const double d[2], double len)
{
    double along = (c[0] - q[0]) * d[0] + (c[1] - q[1]) * d[1];
    if (along <= 0)
        return hypot(c[0] - q[0], c[1] - q[1]);
    if (along >= len)
        return hypot(c[0] - q[0] - len * d[0], c[1] - q[1] - len * d[1]);
    return fabs((c[0] - q[0]) * d[1] - (c[1] - q[1]) * d[0]);
}

/* Is c strictly inside polygon E (anticlockwise, three or more vertices)? */
static int inside(const m2c_world *w, const body *E, const snap *se, const double c[2])
{
    if (E->nvert < 3)
        return 0;
    for (int u = 0; u < E->nvert; u++) {
        double q[2], d[2];
        world_point(se, &w->verts[2 * (E->vert + u)], q);
        world_vector(se, &w->edges[3 * (E->vert + u)], d);
        if ((c[0] - q[0]) * d[1] - (c[1] - q[1]) * d[0] >= 0) /* on the right of an edge */
            return 0;
    }
    return 1;
}

/* Do segments p + s d (s in [0, lp]) and q + r e (r in [0, lq]) cross? */
static int crossing(const double p[2], const double d[2], double lp, const double q[2],
                    const double e[2], double lq)
{
    double den = d[0] * e[1] - d[1] * e[0];
    if (den == 0)
        return 0;
    double qp[2] = {q[0] - p[0], q[1] - p[1]};
    double s = (qp[0] * e[1] - qp[1] * e[0]) / den, r = (qp[0] * d[1] - qp[1] * d[0]) / den;
    return s > 0 && s < lp && r > 0 && r < lq;
}

double shape_gap(const m2c_world *w, int i, int j)
{
    const body *B[2] = {&w->b[i], &w->b[j]};
    snap s[2] = {motion_at(&B[0]->m, w->now), motion_at(&B[1]->m, w->now)};
    double best = INFINITY;
    int overlap = 0;
    for (int side = 0; side < 2; side++) {
        const body *P = B[side], *E = B[1 - side];
        const snap *sp = &s[side], *se = &s[1 - side];
        for (int v = 0; v < P->nvert; v++) {
            double c[2];
            world_point(sp, &w->verts[2 * (P->vert + v)], c);
            if (inside(w, E, se, c))
                overlap = 1;
            for (int u = 0; u < E->nvert; u++) {
                double q[2], d[2];
                world_point(se, &w->verts[2 * (E->vert + u)], q);
                if (u < nedges(E)) {
                    const double *e = &w->edges[3 * (E->vert + u)];
                    world_vector(se, e, d);
                    best = fmin(best, point_segment(c, q, d, e[2]));
                    if (side == 0 && v < nedges(P)) {
                        double pd[2];
                        const double *pe = &w->edges[3 * (P->vert + v)];
                        world_vector(sp, pe, pd);
                        if (crossing(c, pd, pe[2], q, d, e[2]))
                            overlap = 1;
                    }
                } else {
                    best = fmin(best, hypot(c[0] - q[0], c[1] - q[1]));
                }
            }
        }
    }
    double gap = best - B[0]->radius - B[1]->radius;
    return overlap ? -(best + B[0]->radius + B[1]->radius) : gap;
}
