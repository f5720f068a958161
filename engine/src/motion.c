/* motion.c -- exact evaluation of a body's motion at any time after its reference time. */
#include <float.h>
#include <math.h>

#include "engine.h"
#include "max2code_roots.h"

snap motion_at(const motion *m, double t)
{
    double s = t - m->t;
    snap r;
    r.x = m->x + s * (m->vx + 0.5 * m->ax * s);
    r.y = m->y + s * (m->vy + 0.5 * m->ay * s);
    r.vx = m->vx + m->ax * s;
    r.vy = m->vy + m->ay * s;
    r.ax = m->ax;
    r.ay = m->ay;
    r.w = m->w;
    if (m->w == 0.0 || s == 0.0) {
        r.th = m->th;
        r.c = m->c;
        r.s = m->s;
    } else {
        r.th = m->th + m->w * s;
        r.c = cos(r.th);
        r.s = sin(r.th);
    }
    return r;
}

void body_commit(body *b, double t)
{
    if (t == b->m.t)
        return;
    snap s = motion_at(&b->m, t);
    b->m.t = t;
    b->m.x = s.x;
    b->m.y = s.y;
    b->m.vx = s.vx;
    b->m.vy = s.vy;
    if (s.th != b->m.th) {
        /* keep the angle small, so that th + w s keeps its absolute precision */
        b->m.th = remainder(s.th, 2 * 3.14159265358979323846);
        b->m.c = cos(b->m.th);
        b->m.s = sin(b->m.th);
    }
}

void world_vector(const snap *s, const double v[2], double out[2])
{
    out[0] = s->c * v[0] - s->s * v[1];
    out[1] = s->s * v[0] + s->c * v[1];
}

void world_point(const snap *s, const double off[2], double out[2])
{
    double r[2];
    world_vector(s, off, r);
    out[0] = s->x + r[0];
    out[1] = s->y + r[1];
}

/* First time in (0, tmax] at which the coordinate x + v s + a s^2/2 reaches `edge` moving
 * outwards (dir = +1: increasing through it, -1: decreasing), or INFINITY. Just past the edge
 * (rounding, right after crossing it) counts as on it: the next crossing strictly after now;
 * on it (or past it) and moving outwards is a crossing now.
 *
 * The root finder is always given a finite window: the crossing, if there is one, comes
 * before twice the closed form's bound below. With tmax = inf the runtime's window rule
 * misses real roots: 1e-16 + t - 4.905 t^2 had none (issue 33), so a ball one ulp above a cell
 * boundary never crossed it and never met the floor below. */
double first_crossing(double x, double v, double a, double edge, int dir, double tmax)
{
    double d = dir * (edge - x), u = dir * v, h = dir * 0.5 * a;   /* u s + h s^2 = d */
    if (!(d > 0)) {
        d = 0;
        if (u > 0 || (u == 0 && h > 0))
            return 0.0; /* on the edge, leaving: now */
    }
    double bound;
    if (h > 0)
        bound = (fabs(u) + sqrt(u * u + 4 * h * d)) / h;
    else if (u > 0)
        bound = h < 0 ? u / -h : 2 * d / u; /* before the turning point; or linear */
    else
        return INFINITY; /* moving inwards and not accelerating outwards: never */
    double window = fmin(tmax, bound);
    if (!(window > 0))
        return INFINITY;
    if (!(window < INFINITY))
        window = DBL_MAX;
    double c[3] = {d, -u, -h};
    double t;
    int graze = 0;
    if (m2c_first_root_ex(c, 2, window, &t, M2C_METHOD_INTERVAL, &graze) == 1 && !graze)
        return t;
    return INFINITY;
}
