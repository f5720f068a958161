/* motion.c -- exact evaluation of a body's motion at any time after its reference time. */
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
 * (rounding, right after crossing it) counts as on it: the next crossing strictly after now. */
double first_crossing(double x, double v, double a, double edge, int dir, double tmax)
{
    double c[3] = {dir * (edge - x), -dir * v, -dir * 0.5 * a};
    if (c[0] < 0)
        c[0] = 0;
    double t;
    int graze = 0;
    if (m2c_first_root_ex(c, 2, tmax, &t, M2C_METHOD_INTERVAL, &graze) == 1 && !graze)
        return t;
    return INFINITY;
}
