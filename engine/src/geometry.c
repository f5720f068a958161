/* geometry.c -- shapes at one instant: gaps and overlaps between bodies (what set_pose checks
 * before it moves a body), and the collision filter. Prediction never uses these: it finds
 * contacts as roots of the contact polynomials (predict.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "engine.h"

int pair_filtered(const body *a, const body *b)
{
    if (a->group >= 0 && a->group == b->group)
        return 0;
    return (a->category & b->mask) != 0 && (b->category & a->mask) != 0;
}

body part_view(const m2c_world *w, const body *b, int k)
{
    body v = *b;
    const part *p = &w->parts[b->part + k];
    v.vert = p->vert;
    v.nvert = p->nvert;
    v.radius = p->radius;
    v.part = b->part + k;
    v.nparts = 1;
    return v;
}

int vertex_part(const m2c_world *w, const body *b, int v)
{
    int k = 0;
    while (k + 1 < b->nparts && w->parts[b->part + k + 1].vert <= b->vert + v)
        k++;
    return k;
}

double vertex_radius(const m2c_world *w, const body *b, int v)
{
    return b->nparts == 1 ? b->radius : w->parts[b->part + vertex_part(w, b, v)].radius;
}

void body_reach(const m2c_world *w, body *b)
{
    double rho = 0, bound = 0;
    for (int k = 0; k < b->nparts; k++) {
        const part *p = &w->parts[b->part + k];
        for (int v = 0; v < p->nvert; v++) {
            double r = hypot(w->verts[2 * (p->vert + v)], w->verts[2 * (p->vert + v) + 1]);
            rho = fmax(rho, r);
            bound = fmax(bound, r + p->radius);
        }
    }
    b->rho = rho;
    b->bound = bound;
}

/* Shapes as world-frame vertex lists: n points, anticlockwise when n >= 3, and a radius. */
typedef struct {
    double *v;
    int n;
    double r;
} shape;

/* Room for the world-frame vertices of the largest body (NULL when out of memory). */
static double *scratch(const m2c_world *w)
{
    int most = 1;
    for (int i = 0; i < w->n; i++)
        if (w->b[i].nvert > most)
            most = w->b[i].nvert;
    return malloc(sizeof(double) * 2 * (size_t)most);
}

/* Part p of body i's shape at time t (>= its reference time), its vertices into buf. */
static int shape_at(const m2c_world *w, int i, int p, double t, shape *out, double *buf)
{
    const body *b = &w->b[i];
    const part *q = &w->parts[b->part + p];
    out->v = buf;
    snap s = motion_at(&b->m, t < b->m.t ? b->m.t : t);
    for (int k = 0; k < q->nvert; k++)
        world_point(&s, &w->verts[2 * (q->vert + k)], &out->v[2 * k]);
    out->n = q->nvert;
    out->r = q->radius;
    return 0;
}

static int nedges_of(const shape *s)
{
    return s->n >= 3 ? s->n : s->n - 1;
}

/* Edge k of a shape: start q, unit direction d, length; 0 when degenerate. */
static double edge_of(const shape *s, int k, double q[2], double d[2])
{
    const double *p = &s->v[2 * k], *e = &s->v[2 * ((k + 1) % s->n)];
    double len = hypot(e[0] - p[0], e[1] - p[1]);
    q[0] = p[0];
    q[1] = p[1];
    d[0] = len > 0 ? (e[0] - p[0]) / len : 0.0;
    d[1] = len > 0 ? (e[1] - p[1]) / len : 0.0;
    return len;
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

/* Is c strictly inside the polygon (three or more vertices, anticlockwise)? */
static int inside_shape(const shape *s, const double c[2])
{
    if (s->n < 3)
        return 0;
    for (int k = 0; k < s->n; k++) {
        double q[2], d[2];
        edge_of(s, k, q, d);
        if ((c[0] - q[0]) * d[1] - (c[1] - q[1]) * d[0] >= 0) /* on the right of an edge */
            return 0;
    }
    return 1;
}

/* Distance between the cores (vertex lists) of two shapes; -1 when they intersect. */
static double core_distance(const shape *A, const shape *B)
{
    const shape *S[2] = {A, B};
    double best = INFINITY;
    for (int side = 0; side < 2; side++) {
        const shape *P = S[side], *E = S[1 - side];
        for (int v = 0; v < P->n; v++) {
            const double *c = &P->v[2 * v];
            if (inside_shape(E, c))
                return -1;
            if (E->n == 1)
                best = fmin(best, hypot(c[0] - E->v[0], c[1] - E->v[1]));
            for (int u = 0; u < nedges_of(E); u++) {
                double q[2], d[2], len = edge_of(E, u, q, d);
                best = fmin(best, point_segment(c, q, d, len));
                if (side == 0 && v < nedges_of(P)) { /* crossing edges */
                    double pq[2], pd[2], lp = edge_of(P, v, pq, pd);
                    double den = pd[0] * d[1] - pd[1] * d[0];
                    if (den != 0) {
                        double r[2] = {q[0] - pq[0], q[1] - pq[1]};
                        double a = (r[0] * d[1] - r[1] * d[0]) / den, b = (r[0] * pd[1] - r[1] * pd[0]) / den;
                        if (a > 0 && a < lp && b > 0 && b < len)
                            return -1;
                    }
                }
            }
        }
    }
    return best;
}

/* The least of f over the part pairs of bodies i and j at time t (a compound's gap is its
 * nearest parts'); -INFINITY when out of memory. */
static double least_over_parts(const m2c_world *w, int i, int j, double t,
                               double (*f)(const shape *, const shape *))
{
    shape A, B;
    double *va = malloc(sizeof(double) * 2 * (size_t)w->b[i].nvert);
    double *vb = malloc(sizeof(double) * 2 * (size_t)w->b[j].nvert);
    double gap = -INFINITY;
    if (va && vb) {
        gap = INFINITY;
        for (int p = 0; p < w->b[i].nparts; p++) {
            shape_at(w, i, p, t, &A, va);
            for (int q = 0; q < w->b[j].nparts; q++) {
                shape_at(w, j, q, t, &B, vb);
                gap = fmin(gap, f(&A, &B));
            }
        }
    }
    free(va);
    free(vb);
    return gap;
}

static double parts_gap(const shape *A, const shape *B)
{
    double d = core_distance(A, B);
    return d < 0 ? -(A->r + B->r) - 1.0 : d - A->r - B->r;
}

double shape_gap(const m2c_world *w, int i, int j)
{
    return least_over_parts(w, i, j, w->now, parts_gap); /* out of memory: refuse */
}

/* The largest separation of two cores along the edge normals of either (both senses): the
 * separating axis theorem -- positive when some axis separates them, else minus the depth of
 * their overlap (for convex cores the deepest overlap is along an edge normal). */
static double axis_separation(const shape *A, const shape *B)
{
    const shape *S[2] = {A, B};
    double best = -INFINITY;
    for (int side = 0; side < 2; side++) {
        const shape *E = S[side];
        for (int k = 0; k < nedges_of(E); k++) {
            double q[2], d[2];
            if (!(edge_of(E, k, q, d) > 0))
                continue;
            double n[2] = {d[1], -d[0]}, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
            for (int s = 0; s < 2; s++)
                for (int v = 0; v < S[s]->n; v++) {
                    double x = S[s]->v[2 * v] * n[0] + S[s]->v[2 * v + 1] * n[1];
                    lo[s] = fmin(lo[s], x);
                    hi[s] = fmax(hi[s], x);
                }
            best = fmax(best, fmax(lo[1] - hi[0], lo[0] - hi[1]));
        }
    }
    return best;
}

static double parts_signed_gap(const shape *A, const shape *B)
{
    double d = core_distance(A, B);
    if (d < 0) /* the cores intersect: their depth (no axis when both are points) */
        d = fmin(0.0, axis_separation(A, B));
    return d - A->r - B->r;
}

double shape_signed_gap(const m2c_world *w, int i, int j, double t)
{
    return least_over_parts(w, i, j, t, parts_signed_gap); /* out of memory: overlapping */
}

/* ------------------------------------------------------------------------------------------ */
/* Queries at a time t >= now (max2code_engine.h)                                              */
/* ------------------------------------------------------------------------------------------ */

static int query_ok(m2c_world *w, double t)
{
    if (w->broken)
        return 0;
    if (!(t >= w->now) || !isfinite(t)) {
        snprintf(w->err, sizeof w->err, "query: the time must be finite and not before now");
        return 0;
    }
    return 1;
}

static int selectable(const body *b, unsigned int mask)
{
    return b->kind != KIND_REMOVED && (b->category & mask) != 0;
}

int m2c_world_query_point(m2c_world *w, double t, double x, double y, unsigned int mask,
                          int *out, int capacity)
{
    if (!query_ok(w, t))
        return -1;
    int count = 0;
    double c[2] = {x, y};
    double *buf = scratch(w);
    if (!buf)
        return -1;
    for (int i = 0; i < w->n; i++) {
        shape s;
        if (!selectable(&w->b[i], mask))
            continue;
        int in = 0;
        for (int k = 0; k < w->b[i].nparts && !in; k++) {
            shape_at(w, i, k, t, &s, buf);
            shape p = {c, 1, 0.0};
            double d = core_distance(&s, &p);
            in = d <= s.r || inside_shape(&s, c);
        }
        if (in) {
            if (count < capacity)
                out[count] = i;
            count++;
        }
    }
    free(buf);
    return count;
}

int m2c_world_query_box(m2c_world *w, double t, double x0, double y0, double x1, double y1,
                        unsigned int mask, int *out, int capacity)
{
    if (!query_ok(w, t))
        return -1;
    if (!(x0 <= x1 && y0 <= y1)) {
        snprintf(w->err, sizeof w->err, "query_box: needs x0 <= x1 and y0 <= y1");
        return -1;
    }
    double corners[8] = {x0, y0, x1, y0, x1, y1, x0, y1};
    shape box = {corners, 4, 0.0};
    if (x0 == x1 || y0 == y1) { /* a degenerate box: a segment or a point */
        box.n = x0 == x1 && y0 == y1 ? 1 : 2;
        corners[2] = x1;
        corners[3] = y1;
    }
    int count = 0;
    double *buf = scratch(w);
    if (!buf)
        return -1;
    for (int i = 0; i < w->n; i++) {
        shape s;
        if (!selectable(&w->b[i], mask))
            continue;
        int in = 0;
        for (int k = 0; k < w->b[i].nparts && !in; k++) {
            shape_at(w, i, k, t, &s, buf);
            in = core_distance(&s, &box) <= s.r;
        }
        if (in) {
            if (count < capacity)
                out[count] = i;
            count++;
        }
    }
    free(buf);
    return count;
}

/* The smallest s in [0, 1] at which p + s d enters the disc (c, r), or INFINITY. */
static double ray_disc(const double p[2], const double d[2], const double c[2], double r)
{
    double f[2] = {p[0] - c[0], p[1] - c[1]};
    double a = d[0] * d[0] + d[1] * d[1], b = f[0] * d[0] + f[1] * d[1];
    double cc = f[0] * f[0] + f[1] * f[1] - r * r;
    if (cc <= 0 || b >= 0 || a == 0)
        return INFINITY; /* inside already, or moving away */
    double disc = b * b - a * cc;
    if (disc < 0)
        return INFINITY;
    double s = cc / (-b + sqrt(disc)); /* the smaller root, without cancellation */
    return s <= 1 ? s : INFINITY;
}

/* The first entry of the ray p + f d (f in [0, *best)) into shape s: 1 when it improved *best
 * (and bn, the surface normal there), else 0. */
static int ray_shape(const shape *s, const double p[2], const double d[2], double *best,
                     double bn[2])
{
    int improved = 0;
    if (s->r > 0)
        for (int k = 0; k < s->n; k++) {
            double c[2] = {s->v[2 * k], s->v[2 * k + 1]};
            double f = ray_disc(p, d, c, s->r);
            if (f < *best) {
                double h[2] = {p[0] + f * d[0] - c[0], p[1] + f * d[1] - c[1]};
                double hl = hypot(h[0], h[1]);
                *best = f;
                improved = 1;
                bn[0] = h[0] / hl;
                bn[1] = h[1] / hl;
            }
        }
    for (int k = 0; k < nedges_of(s); k++) {
        double q[2], e[2], len = edge_of(s, k, q, e);
        for (int side = 1; side >= (s->n >= 3 ? 1 : -1); side -= 2) {
            double n[2] = {side * e[1], -side * e[0]}; /* outward (right of an anticlockwise edge) */
            double dn = d[0] * n[0] + d[1] * n[1];
            if (!(dn < 0))
                continue;
            double h = (p[0] - q[0]) * n[0] + (p[1] - q[1]) * n[1] - s->r; /* height above the face */
            if (h < 0)
                continue;
            double f = h / -dn;
            if (!(f <= 1) || !(f < *best))
                continue;
            double at[2] = {p[0] + f * d[0] - q[0], p[1] + f * d[1] - q[1]};
            double along = at[0] * e[0] + at[1] * e[1];
            if (along < 0 || along > len)
                continue;
            *best = f;
            improved = 1;
            bn[0] = n[0];
            bn[1] = n[1];
        }
    }
    return improved;
}

int m2c_world_cast_ray(m2c_world *w, double t, double x0, double y0, double x1, double y1,
                       unsigned int mask, double *fraction, int *body, double normal[2])
{
    if (!query_ok(w, t))
        return -1;
    double p[2] = {x0, y0}, d[2] = {x1 - x0, y1 - y0};
    double best = INFINITY;
    int hit = -1;
    double bn[2] = {0, 0};
    double *buf = scratch(w);
    if (!buf)
        return -1;
    for (int i = 0; i < w->n; i++) {
        shape s;
        if (!selectable(&w->b[i], mask))
            continue;
        shape start = {p, 1, 0.0};
        int inside = 0;
        for (int k = 0; k < w->b[i].nparts && !inside; k++) {
            shape_at(w, i, k, t, &s, buf);
            double d0 = core_distance(&s, &start);
            inside = d0 < s.r || d0 < 0; /* the ray starts inside it: not a hit (as Box2D) */
        }
        if (inside)
            continue;
        for (int part = 0; part < w->b[i].nparts; part++) {
            shape_at(w, i, part, t, &s, buf);
            if (ray_shape(&s, p, d, &best, bn))
                hit = i;
        }
    }
    free(buf);
    if (hit < 0)
        return 0;
    *fraction = best;
    *body = hit;
    normal[0] = bn[0];
    normal[1] = bn[1];
    return 1;
}
