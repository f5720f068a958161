/*
 * edit.c -- changing bodies at the world's current time: removal, pose, velocity,
 * acceleration, mass, kind, impulses (max2code_engine.h).
 *
 * Every change commits the body's motion at now, edits it, bumps its motion counter (events
 * of other bodies that name it as partner become stale) and predicts again what depends on it
 * at once, so that the queue is right before the next event:
 *   - a dynamic body: itself, and every dynamic body whose pending contact is with it;
 *   - a kinematic body: every dynamic body (each one checks every kinematic body);
 *   - a static body: the broad phase's static lists are rebuilt and everything predicted
 *     again at the next step (prepare).
 * Bodies resting on the changed body or asleep against it wake first: what held them may
 * have moved away.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "engine.h"

static int fail(m2c_world *w, const char *what, const char *msg)
{
    snprintf(w->err, sizeof w->err, "%s: %s", what, msg);
    return -1;
}

/* 0 when body i exists; else -1 with the error set. */
static int check_body(m2c_world *w, int i, const char *what)
{
    if (w->broken)
        return -1;
    if (i < 0 || i >= w->n)
        return fail(w, what, "no such body");
    if (w->b[i].kind == KIND_REMOVED)
        return fail(w, what, "the body was removed");
    if (w->in_presolve)
        return fail(w, what, "no changes inside the pre-solve callback");
    return 0;
}

static int finite3(double a, double b, double c)
{
    return isfinite(a) && isfinite(b) && isfinite(c);
}

/* Near enough now that i may hold k (or touch it): their bounding circles within a slack. */
static int near(const m2c_world *w, int i, int k)
{
    const body *I = &w->b[i], *K = &w->b[k];
    snap a = motion_at(&I->m, w->now), b = motion_at(&K->m, w->now);
    double reach = I->bound + K->bound + 1e-6 * (I->bound + K->bound) + 2 * w->cfg.tolerance;
    if (I->kind == M2C_STATIC && I->nvert > 1)  /* a wall's circle is too large to tell */
        return shape_gap(w, i, k) <= 1e-6 * K->bound + 2 * w->cfg.tolerance;
    return hypot(a.x - b.x, a.y - b.y) <= reach;
}

static void predict_woken(m2c_world *w, int count)
{
    if (!w->prepared)
        return;
    for (int k = 0; k < count; k++)
        world_predict(w, w->woken[k]);
}

/* Wake what rests on body i or sleeps against it. */
static void wake_around(m2c_world *w, int i)
{
    for (int k = 0; k < w->n; k++) {
        body *K = &w->b[k];
        if (k == i || K->kind != M2C_DYNAMIC || K->state == AWAKE)
            continue;
        if (K->support != i && !near(w, i, k))
            continue;
        if (body_still(K)) {
            predict_woken(w, wake_island(w, k, w->woken, w->cap));
        } else {
            rest_restore(w, k);
            if (w->prepared)
                world_predict(w, k);
        }
    }
}

/* Predict again what depends on body i, whose motion just changed (see the file's comment). */
static void changed(m2c_world *w, int i)
{
    body *b = &w->b[i];
    b->counter++;
    if (!w->prepared)
        return;
    if (b->kind == M2C_STATIC || (b->kind == M2C_DYNAMIC && b->bound > w->bound_max)) {
        w->prepared = 0;
        return;
    }
    for (int k = 0; k < w->n; k++) {
        const body *K = &w->b[k];
        if (k == i || K->kind != M2C_DYNAMIC)
            continue;
        if (b->kind == M2C_KINEMATIC || (K->ev.kind == EV_CONTACT && K->ev.partner == i))
            world_predict(w, k);
    }
    if (b->kind == M2C_DYNAMIC)
        world_predict(w, i);
}

/* Commit the body at now and wake what it holds: before any edit of a body's motion. */
static void begin_edit(m2c_world *w, int i)
{
    solver_forget(w, i); /* an edited body flies again; its next slow contact hands it back */
    wake_around(w, i);
    body *b = &w->b[i];
    if (b->kind == M2C_DYNAMIC) {
        if (b->state == ASLEEP || body_still(b))
            predict_woken(w, wake_island(w, i, w->woken, w->cap));
        rest_restore(w, i);
    }
    body_commit(b, w->now);
}

int m2c_world_remove_body(m2c_world *w, int i)
{
    if (check_body(w, i, "remove_body") != 0)
        return -1;
    begin_edit(w, i);
    body *b = &w->b[i];
    int kind = b->kind;
    b->m.vx = b->m.vy = b->m.ax = b->m.ay = b->m.w = 0.0;
    if (kind == M2C_DYNAMIC && w->prepared) {
        heap_remove(w, i);
        grid_remove(w, i);
    }
    if (kind == M2C_KINEMATIC) {
        int k = 0;
        while (w->kinematic[k] != i)
            k++;
        memmove(w->kinematic + k, w->kinematic + k + 1, sizeof(int) * (size_t)(w->nkin - k - 1));
        w->nkin--;
    }
    b->kind = KIND_REMOVED;
    b->counter++;
    ghost_forget(w, i);
    b->ev.t = INFINITY;
    b->ev.kind = EV_NONE;
    if (!w->prepared)
        return 0;
    /* the bodies whose next contact was with it look again now (the static lists keep it,
     * skipped: removal costs no rebuild) */
    for (int k = 0; k < w->n; k++) {
        const body *K = &w->b[k];
        if (K->kind == M2C_DYNAMIC && K->ev.kind == EV_CONTACT && K->ev.partner == i)
            world_predict(w, k);
    }
    return 0;
}

int m2c_world_body_alive(const m2c_world *w, int i)
{
    return i >= 0 && i < w->n && w->b[i].kind != KIND_REMOVED;
}

int m2c_world_set_velocity(m2c_world *w, int i, double vx, double vy, double omega)
{
    if (check_body(w, i, "set_velocity") != 0)
        return -1;
    if (!finite3(vx, vy, omega))
        return fail(w, "set_velocity", "not finite");
    if (w->b[i].kind == M2C_STATIC)
        return fail(w, "set_velocity", "a static body does not move (make it kinematic or dynamic)");
    begin_edit(w, i);
    body *b = &w->b[i];
    b->m.vx = vx;
    b->m.vy = vy;
    b->m.w = omega;
    changed(w, i);
    return 0;
}

int m2c_world_set_acceleration(m2c_world *w, int i, double ax, double ay)
{
    if (check_body(w, i, "set_acceleration") != 0)
        return -1;
    if (!isfinite(ax) || !isfinite(ay))
        return fail(w, "set_acceleration", "not finite");
    if (w->b[i].kind == M2C_STATIC)
        return fail(w, "set_acceleration", "a static body does not move (make it kinematic or dynamic)");
    begin_edit(w, i);
    body *b = &w->b[i];
    b->m.ax = b->gx = ax;
    b->m.ay = b->gy = ay;
    changed(w, i);
    return 0;
}

int m2c_world_set_pose(m2c_world *w, int i, double x, double y, double angle)
{
    if (check_body(w, i, "set_pose") != 0)
        return -1;
    if (!finite3(x, y, angle))
        return fail(w, "set_pose", "not finite");
    body *b = &w->b[i];
    motion old = b->m;
    body_commit(b, w->now);
    b->m.x = x;
    b->m.y = y;
    b->m.th = angle;
    b->m.c = cos(angle);
    b->m.s = sin(angle);
    for (int k = 0; k < w->n; k++) {
        const body *K = &w->b[k];
        if (k == i || K->kind == KIND_REMOVED || !pair_filtered(b, K))
            continue;
        if (b->kind != M2C_DYNAMIC && K->kind != M2C_DYNAMIC)
            continue; /* they never meet */
        if (shape_gap(w, i, k) < -w->cfg.tolerance) {
            b->m = old;
            snprintf(w->err, sizeof w->err, "set_pose: body %d would overlap body %d there", i, k);
            return -1;
        }
    }
    b->m = old;
    begin_edit(w, i);           /* what rested on it at its old place */
    b->m.x = x;
    b->m.y = y;
    b->m.th = angle;
    b->m.c = cos(angle);
    b->m.s = sin(angle);
    if (b->kind == M2C_DYNAMIC && w->prepared) {
        grid_remove(w, i);
        grid_insert(w, i);
    }
    wake_around(w, i);          /* what sleeps against it at its new place */
    ghost_leave_sensors(w, i);  /* it overlaps nothing there (checked above) */
    changed(w, i);
    return 0;
}

int m2c_world_set_mass(m2c_world *w, int i, double mass, double inertia, double cx, double cy)
{
    if (check_body(w, i, "set_mass") != 0)
        return -1;
    if (!(mass > 0 && inertia > 0 && isfinite(mass) && isfinite(inertia)) || !isfinite(cx)
        || !isfinite(cy))
        return fail(w, "set_mass", "mass and inertia must be positive, the centre finite");
    begin_edit(w, i);
    body *b = &w->b[i];
    b->dmass = mass;
    b->dinertia = inertia;
    if (b->kind == M2C_DYNAMIC) {
        b->mass = mass;
        b->inertia = inertia;
        b->inv_mass = 1 / mass;
        b->inv_inertia = 1 / inertia;
    }
    if (cx != 0 || cy != 0) {
        /* the reference point moves to the centre, the vertices the other way */
        for (int k = 0; k < b->nvert; k++) {
            double *p = &w->verts[2 * (b->vert + k)];
            p[0] -= cx;
            p[1] -= cy;
        }
        double off[2] = {cx, cy}, r[2];
        snap s = motion_at(&b->m, w->now);
        world_vector(&s, off, r);
        b->m.x += r[0];
        b->m.y += r[1];
        /* a turning body's points keep their velocities: v + w x r */
        b->m.vx -= b->m.w * r[1];
        b->m.vy += b->m.w * r[0];
        body_reach(w, b);
        if (b->kind == M2C_DYNAMIC && w->prepared) {
            grid_remove(w, i);
            grid_insert(w, i);
        }
        if (b->kind == M2C_STATIC)
            w->prepared = 0;
    }
    changed(w, i);
    return 0;
}

int m2c_world_set_kind(m2c_world *w, int i, int kind)
{
    if (check_body(w, i, "set_kind") != 0)
        return -1;
    if (kind != M2C_STATIC && kind != M2C_KINEMATIC && kind != M2C_DYNAMIC)
        return fail(w, "set_kind", "kind must be static, kinematic or dynamic");
    body *b = &w->b[i];
    if (kind == b->kind)
        return 0;
    if (kind == M2C_DYNAMIC && !(b->dmass > 0))
        return fail(w, "set_kind", "a dynamic body needs a mass (give one first: set_mass)");
    const char *why = moving_vertices_refusal(kind, b->nvert);
    if (why)
        return fail(w, "set_kind", why);
    begin_edit(w, i);
    if (b->kind == M2C_DYNAMIC && w->prepared) {
        heap_remove(w, i);
        grid_remove(w, i);
    }
    if (b->kind == M2C_KINEMATIC) {
        int k = 0;
        while (w->kinematic[k] != i)
            k++;
        memmove(w->kinematic + k, w->kinematic + k + 1, sizeof(int) * (size_t)(w->nkin - k - 1));
        w->nkin--;
    }
    int was = b->kind;
    b->kind = kind;
    if (kind == M2C_DYNAMIC) {
        b->mass = b->dmass;
        b->inertia = b->dinertia;
        b->inv_mass = 1 / b->mass;
        b->inv_inertia = 1 / b->inertia;
        b->state = AWAKE;
        b->ev.t = INFINITY;
        b->ev.kind = EV_NONE;
        b->m.ax = b->gx;
        b->m.ay = b->gy;
    } else {
        b->mass = b->inertia = INFINITY;
        b->inv_mass = b->inv_inertia = 0.0;
        b->state = AWAKE;
        if (kind == M2C_STATIC)
            b->m.vx = b->m.vy = b->m.ax = b->m.ay = b->m.w = 0.0;
        else
            w->kinematic[w->nkin++] = i;
    }
    if (was == M2C_STATIC || kind == M2C_STATIC || kind == M2C_DYNAMIC)
        w->prepared = 0; /* the static lists change; a new dynamic body joins heap and grid */
    changed(w, i);
    return 0;
}

int m2c_world_apply_impulse(m2c_world *w, int i, double jx, double jy, double px, double py)
{
    if (check_body(w, i, "apply_impulse") != 0)
        return -1;
    if (!isfinite(jx) || !isfinite(jy) || !isfinite(px) || !isfinite(py))
        return fail(w, "apply_impulse", "not finite");
    if (w->b[i].kind != M2C_DYNAMIC)
        return fail(w, "apply_impulse", "not a dynamic body");
    begin_edit(w, i);
    body *b = &w->b[i];
    double rx = px - b->m.x, ry = py - b->m.y;
    b->m.vx += jx * b->inv_mass;
    b->m.vy += jy * b->inv_mass;
    b->m.w += (rx * jy - ry * jx) * b->inv_inertia;
    changed(w, i);
    return 0;
}

int m2c_world_set_flags(m2c_world *w, int i, int flags)
{
    if (check_body(w, i, "set_flags") != 0)
        return -1;
    if (flags & ~(M2C_FLAG_SENSOR | M2C_FLAG_PRESOLVE | M2C_FLAG_SEPARATE))
        return fail(w, "set_flags", "unknown flag");
    w->b[i].flags = flags;
    w->any_sensor |= (flags & M2C_FLAG_SENSOR) != 0;
    return 0;
}

void m2c_world_set_presolve(m2c_world *w, m2c_presolve_fn fn, void *user)
{
    w->presolve = fn;
    w->presolve_user = user;
}

int m2c_world_vertices(const m2c_world *w, int i, double *out, int capacity)
{
    if (i < 0 || i >= w->n)
        return -1;
    const body *b = &w->b[i];
    for (int k = 0; k < b->nvert && k < capacity; k++) {
        out[2 * k] = w->verts[2 * (b->vert + k)];
        out[2 * k + 1] = w->verts[2 * (b->vert + k) + 1];
    }
    return b->nvert;
}

int m2c_world_parts(const m2c_world *w, int i, int *counts, double *radii, int capacity)
{
    if (i < 0 || i >= w->n)
        return -1;
    const body *b = &w->b[i];
    for (int k = 0; k < b->nparts && k < capacity; k++) {
        if (counts)
            counts[k] = w->parts[b->part + k].nvert;
        if (radii)
            radii[k] = w->parts[b->part + k].radius;
    }
    return b->nparts;
}
