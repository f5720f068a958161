/*
 * world.c -- the world: bodies, the event loop and the public API.
 *
 * The loop pops the earliest event (a body's predicted contact, cell crossing or window
 * end, or a timer), advances only the bodies it involves, responds, and predicts those
 * bodies again; everything else keeps its state at its own last event time.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine.h"

#define HORIZON 1e6 /* seconds: see horizon() */
#define WORK_EVENTS 4096       /* events per call of m2c_world_step, then it returns 1 */
#define WORK_SOLVES 2000000    /* root solves per call, likewise (about 0.1 to 1 s) */
#define SAME_TIME_LIMIT 100000 /* events within STUCK_SPAN of one time: the step gives up */
#define STUCK_SPAN 1e-6 /* s, relative to 1 + |t| */
#define MAX_VERTICES (1 << 24) /* a body's, all parts together: 2 * n and the sums fit int */

static int fail(m2c_world *w, const char *msg)
{
    snprintf(w->err, sizeof w->err, "%s", msg);
    return -1;
}

m2c_world *m2c_world_new(const m2c_config *config)
{
    m2c_world *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    if (config)
        w->cfg = *config;
    if (!(w->cfg.tolerance > 0) || !isfinite(w->cfg.tolerance))
        w->cfg.tolerance = 1e-9;
    if (!(w->cfg.contact_step > 0) || !isfinite(w->cfg.contact_step))
        w->cfg.contact_step = 0.0; /* the contact solver off (negative, NaN or infinite) */
    w->broken = predict_check_generated(w) != 0; /* reported by every call that needs it */
    return w;
}

void m2c_world_free(m2c_world *w)
{
    if (!w)
        return;
    free(w->b);
    free(w->verts);
    free(w->edges);
    free(w->parts);
    free(w->heap);
    free(w->heap_pos);
    free(w->kinematic);
    free(w->stack);
    free(w->woken);
    free(w->members);
    free(w->pending);
    free(w->timers);
    free(w->ghosts);
    solver_free(w);
    grid_free(&w->g);
    free(w);
}

const char *m2c_world_error(const m2c_world *w)
{
    return w->err;
}

int m2c_world_body_count(const m2c_world *w)
{
    return w->n;
}

double m2c_world_time(const m2c_world *w)
{
    return w->now;
}

static int finite_all(const double *v, int n)
{
    for (int k = 0; k < n; k++)
        if (!isfinite(v[k]))
            return 0;
    return 1;
}

m2c_body_def m2c_default_body_def(void)
{
    m2c_body_def d;
    memset(&d, 0, sizeof d);
    d.kind = M2C_DYNAMIC;
    d.mass = 1.0;
    d.inertia = 1.0;
    d.restitution = 1.0;
    d.group = -1;
    d.category = 1u;
    d.mask = ~0u;
    d.internal = DEF_COOKIE;
    return d;
}

/* The signed turn at vertex k + 1 of a closed polygon. */
static double turn(const double *v, int n, int k)
{
    const double *p = &v[2 * k], *q = &v[2 * ((k + 1) % n)], *r = &v[2 * ((k + 2) % n)];
    return (q[0] - p[0]) * (r[1] - q[1]) - (q[1] - p[1]) * (r[0] - q[0]);
}

/* One convex shape (a single-shape body's or a compound's part): 0, or -1 with the error set
 * (prefixed by `where`: which part). */
static int check_shape(m2c_world *w, const char *where, int n, const double *v, double radius)
{
    const char *why = NULL;
    if (n < 1 || !v)
        why = "a body needs at least one vertex";
    else if (n > MAX_VERTICES)
        why = "a body has at most 16777216 vertices";
    else if (!finite_all(v, 2 * n))
        why = "a vertex is not finite";
    else if (!isfinite(radius))
        why = "a number of the body is not finite";
    else if (radius < 0)
        why = "the radius must not be negative";
    else if (n == 1 && !(radius > 0))
        why = "a circle needs a positive radius";
    for (int k = 0; !why && (k + 1 < n || (n >= 3 && k < n)); k++) {
        int m = (k + 1) % n;
        if (v[2 * k] == v[2 * m] && v[2 * k + 1] == v[2 * m + 1])
            why = "two consecutive vertices coincide";
    }
    if (!why && n >= 3) {
        /* either winding: every turn the same way (clockwise polygons are stored reversed) */
        double first = turn(v, n, 0);
        for (int k = 0; k < n && !why; k++) {
            double c = turn(v, n, k);
            if (!(first > 0 ? c > 0 : c < 0))
                why = "a polygon must be convex (no three vertices in a line)";
        }
    }
    if (!why)
        return 0;
    snprintf(w->err, sizeof w->err, "%s%s", where, why);
    return -1;
}

/* A moving body's vertices are bounded (MAX_MOVING_VERTICES: why, in engine.h). */
const char *moving_vertices_refusal(int kind, long long nvertices)
{
    return kind != M2C_STATIC && nvertices > MAX_MOVING_VERTICES
               ? "a dynamic or kinematic body has at most 128 vertices (all its parts together; "
                 "a static one may have more)"
               : NULL;
}

static int check_moving(m2c_world *w, int kind, long long nvertices)
{
    const char *why = moving_vertices_refusal(kind, nvertices);
    return why ? fail(w, why) : 0;
}

static int check_def(m2c_world *w, const m2c_body_def *d)
{
    if (w->broken)
        return -1;
    if (d->internal != DEF_COOKIE)
        return fail(w, "the body def was not made by m2c_default_body_def()");
    if (d->kind != M2C_STATIC && d->kind != M2C_KINEMATIC && d->kind != M2C_DYNAMIC)
        return fail(w, "kind must be static, kinematic or dynamic");
    double nums[] = {d->x, d->y, d->angle, d->vx, d->vy, d->omega, d->ax, d->ay, d->radius,
                     d->restitution, d->friction};
    if (!finite_all(nums, (int)(sizeof nums / sizeof nums[0])))
        return fail(w, "a number of the body is not finite");
    if (d->nparts < 0 || (d->nparts > 0 && !d->parts))
        return fail(w, "a compound body needs its parts (nparts >= 1 and parts)");
    if (d->nparts == 0 && d->parts)
        return fail(w, "a compound body needs at least one part (nparts is 0)");
    if (d->nparts > 0 && (d->nvertices != 0 || d->vertices || d->radius != 0))
        return fail(w, "a compound body's shape is its parts: leave nvertices, vertices and "
                       "radius unset");
    if (d->restitution < 0 || d->restitution > 1)
        return fail(w, "restitution must be between 0 and 1");
    if (d->friction < 0)
        return fail(w, "friction must not be negative");
    if (d->flags & ~(M2C_FLAG_SENSOR | M2C_FLAG_PRESOLVE | M2C_FLAG_SEPARATE))
        return fail(w, "unknown flag");
    if (d->kind == M2C_DYNAMIC && !(d->mass > 0 && d->inertia > 0 && isfinite(d->mass)
                                    && isfinite(d->inertia)))
        return fail(w, "a dynamic body needs a positive mass and moment of inertia");
    if (d->nparts == 0)
        return check_shape(w, "", d->nvertices, d->vertices, d->radius) != 0 ? -1
               : check_moving(w, d->kind, d->nvertices);
    long long total = 0;
    for (int p = 0; p < d->nparts; p++) {
        char where[48];
        snprintf(where, sizeof where, "part %d of %d: ", p, d->nparts);
        const m2c_part *q = &d->parts[p];
        if (check_shape(w, where, q->nvertices, q->vertices, q->radius) != 0)
            return -1;
        total += q->nvertices;
        if (total > MAX_VERTICES)   /* before the parts' counts overflow the sum */
            return fail(w, "a body has at most 16777216 vertices (all its parts together)");
    }
    return check_moving(w, d->kind, total);
}

static int grow(m2c_world *w, int nverts, int nparts)
{
    if (w->nparts + nparts > w->capparts) {
        int cap = w->capparts ? 2 * w->capparts : 16;
        while (cap < w->nparts + nparts)
            cap *= 2;
        part *p = realloc(w->parts, sizeof(part) * (size_t)cap);
        if (!p)
            return -1;
        w->parts = p;
        w->capparts = cap;
    }
    if (w->n == w->cap) {
        int cap = w->cap ? 2 * w->cap : 16;
        body *b = realloc(w->b, sizeof(body) * (size_t)cap);
        if (!b)
            return -1;
        w->b = b;
        w->cap = cap;
        if (heap_init(w, cap) != 0)
            return -1;
        int *k = realloc(w->kinematic, sizeof(int) * (size_t)cap);
        if (!k)
            return -1;
        w->kinematic = k;
        int *st = realloc(w->stack, sizeof(int) * (size_t)cap);
        if (!st)
            return -1;
        w->stack = st;
        int *wk = realloc(w->woken, sizeof(int) * (size_t)cap);
        if (!wk)
            return -1;
        w->woken = wk;
        int *mb = realloc(w->members, sizeof(int) * (size_t)cap);
        if (!mb)
            return -1;
        w->members = mb;
    }
    if (w->nverts + nverts > w->capverts) {
        int cap = w->capverts ? 2 * w->capverts : 64;
        while (cap < w->nverts + nverts)
            cap *= 2;
        double *v = realloc(w->verts, sizeof(double) * 2 * (size_t)cap);
        if (!v)
            return -1;
        w->verts = v;
        double *e = realloc(w->edges, sizeof(double) * 3 * (size_t)cap);
        if (!e)
            return -1;
        w->edges = e;
        w->capverts = cap;
    }
    return 0;
}

static void predict_all(m2c_world *w)
{
    for (int i = 0; i < w->n; i++)
        if (w->b[i].kind == M2C_DYNAMIC)
            world_predict(w, i);
}

static int prepare(m2c_world *w)
{
    if (grid_build(w) != 0)
        return fail(w, "out of memory");
    w->heap_n = 0;
    for (int i = 0; i < w->n; i++) {
        w->heap_pos[i] = -1;
        if (w->b[i].kind == M2C_DYNAMIC) {
            w->b[i].ev.t = INFINITY;
            w->b[i].ev.kind = EV_NONE;
            heap_insert(w, i);
        }
    }
    w->prepared = 1;
    predict_all(w);
    return 0;
}

/* A shape's vertices (anticlockwise: a clockwise polygon reversed) and its edges from
 * vertex k to the next, at w->verts / w->edges from index `at`. */
static void store_shape(m2c_world *w, int at, int n, const double *v)
{
    int reversed = n >= 3 && turn(v, n, 0) < 0;
    for (int k = 0; k < n; k++) {
        int from = reversed ? n - 1 - k : k;
        const double *p = &v[2 * from];
        w->verts[2 * (at + k)] = p[0];
        w->verts[2 * (at + k) + 1] = p[1];
        int next = reversed ? (from + n - 1) % n : (from + 1) % n;
        const double *q = &v[2 * next];
        double len = hypot(q[0] - p[0], q[1] - p[1]);
        double *e = &w->edges[3 * (at + k)];
        e[0] = len > 0 ? (q[0] - p[0]) / len : 0.0;
        e[1] = len > 0 ? (q[1] - p[1]) / len : 0.0;
        e[2] = len;
    }
}

int m2c_world_add_body(m2c_world *w, const m2c_body_def *d)
{
    if (!w || !d)
        return -1;
    if (w->in_presolve)
        return fail(w, "add_body: no changes inside the pre-solve callback");
    if (check_def(w, d) != 0)
        return -1;
    /* a single shape is a compound of one part */
    m2c_part single = {d->nvertices, d->vertices, d->radius};
    const m2c_part *parts = d->nparts > 0 ? d->parts : &single;
    int nparts = d->nparts > 0 ? d->nparts : 1, total = 0;
    for (int k = 0; k < nparts; k++)
        total += parts[k].nvertices;
    if (grow(w, total, nparts) != 0)
        return fail(w, "out of memory");
    int i = w->n++;
    body *b = &w->b[i];
    memset(b, 0, sizeof *b);
    b->kind = d->kind;
    b->m = (motion){w->now, d->x, d->y, d->vx, d->vy, d->ax, d->ay, d->angle, d->omega,
                    cos(d->angle), sin(d->angle)};
    if (d->kind == M2C_DYNAMIC) {
        b->mass = d->mass;
        b->inertia = d->inertia;
        b->inv_mass = 1 / d->mass;
        b->inv_inertia = 1 / d->inertia;
    } else {
        b->mass = b->inertia = INFINITY;
        if (d->kind == M2C_STATIC)
            b->m.vx = b->m.vy = b->m.ax = b->m.ay = b->m.w = 0.0;
    }
    b->restitution = d->restitution;
    b->friction = d->friction;
    b->radius = parts[0].radius;
    b->nvert = total;
    b->vert = w->nverts;
    b->part = w->nparts;
    b->nparts = nparts;
    b->group = d->group;
    b->category = d->category;
    b->mask = d->mask;
    b->flags = d->flags;
    if (d->mass > 0 && d->inertia > 0 && isfinite(d->mass) && isfinite(d->inertia)) {
        b->dmass = d->mass;
        b->dinertia = d->inertia;
    }
    b->support = -1;
    b->gx = b->m.ax;
    b->gy = b->m.ay;
    b->rest_time = NAN;
    b->state = AWAKE;
    b->last_contact = -INFINITY;
    b->next = b->prev = -1;
    b->ev.t = INFINITY;
    b->ev.kind = EV_NONE;
    w->heap_pos[i] = -1;
    for (int k = 0; k < nparts; k++) {
        part *q = &w->parts[w->nparts++];
        q->vert = w->nverts;
        q->nvert = parts[k].nvertices;
        q->radius = parts[k].radius;
        store_shape(w, q->vert, parts[k].nvertices, parts[k].vertices);
        w->nverts += parts[k].nvertices;
    }
    body_reach(w, b);
    if (d->kind == M2C_KINEMATIC)
        w->kinematic[w->nkin++] = i;
    w->any_sensor |= (d->flags & M2C_FLAG_SENSOR) != 0;
    if (w->any_sensor)
        ghost_enter_sensors(w, i); /* one that starts inside a sensor enters it now */
    if (w->prepared) {
        if (d->kind == M2C_DYNAMIC && b->bound <= w->bound_max) {
            grid_insert(w, i);
            heap_insert(w, i);
            world_predict(w, i);
        } else {
            w->prepared = 0; /* rebuilt (and everything predicted again) at the next step */
        }
    }
    return i;
}

int world_emit(m2c_world *w, const m2c_event *e)
{
    if (w->out && w->out_n < w->out_cap && w->npending == 0) {
        w->out[w->out_n++] = *e;
        return 0;
    }
    if (w->npending == w->cappending) {
        int cap = w->cappending ? 2 * w->cappending : 64;
        m2c_event *p = realloc(w->pending, sizeof(m2c_event) * (size_t)cap);
        if (!p)
            return -1;
        w->pending = p;
        w->cappending = cap;
    }
    w->pending[w->npending++] = *e;
    return 0;
}

/* Hand out events that did not fit last time; 1 when some are still waiting. */
static int flush_pending(m2c_world *w)
{
    int k = 0;
    while (k < w->npending && w->out_n < w->out_cap)
        w->out[w->out_n++] = w->pending[k++];
    if (k > 0 && k < w->npending) /* (memmove of NULL, even 0 bytes, is undefined) */
        memmove(w->pending, w->pending + k, sizeof(m2c_event) * (size_t)(w->npending - k));
    w->npending -= k;
    return w->npending > 0;
}

typedef struct {
    contact c;
    int partner;
    int batch;        /* every solver body is predicted now: a pair of them from one side */
    const int *marks; /* or: the bodies marked here are predicted now (world_predict_marked) */
} best_contact;

static void visit(m2c_world *w, int i, int j, void *ctx)
{
    best_contact *bc = ctx;
    if (j < i && (bc->marks ? bc->marks[j] != 0 : bc->batch && solver_has(w, j)))
        return; /* j predicts the pair (world_predict_solver, world_predict_marked) */
    if (predict_pair(w, i, j, &bc->c))
        bc->partner = j;
}

/* The search's outcome into the body's event: its contact, or a window end. */
static void set_contact(const m2c_world *w, event *ev, best_contact *bc)
{
    if (bc->c.window < bc->c.t) { /* a rotating search stopped early: resume by then */
        ev->t = bc->c.window;
        ev->kind = EV_WINDOW;
        bc->partner = -1;
    }
    if (bc->partner >= 0) {
        ev->t = bc->c.t;
        ev->kind = EV_CONTACT;
        ev->partner = bc->partner;
        ev->partner_counter = w->b[bc->partner].counter;
        ev->feature = bc->c.feature;
        ev->fa = bc->c.fa;
        ev->fb = bc->c.fb;
        ev->side = bc->c.side;
        ev->up = bc->c.up;
    }
}

/* How far ahead a body with no other event is searched: a million seconds, or a millionth of
 * the time now (so that now + horizon is a later time), at most to the largest double. */
static double horizon(double now)
{
    double h = fmax(HORIZON, 1e-6 * fabs(now));
    return now + h < DBL_MAX ? h : DBL_MAX - now;
}

static void predict_body(m2c_world *w, int i, int batch, const int *marks);

void world_predict(m2c_world *w, int i)
{
    predict_body(w, i, 0, NULL);
}

/* Body i, one of the contact solver's bodies, all of which the tick predicts again at once:
 * a pair of two of them is searched from its lower id's side alone (the other would find the
 * same contact; the searches were a quarter of a dense 200-disc pile's time). When either
 * body's motion changes later, world_predict searches all its pairs again. */
void world_predict_solver(m2c_world *w, int i)
{
    predict_body(w, i, 1, NULL);
}

/* Body i, one of a set whose motions all changed at this instant and which are all predicted
 * again now (marks[j] != 0 for each of them): a pair of two of them from its lower id's side
 * alone, as world_predict_solver. */
void world_predict_marked(m2c_world *w, int i, const int *marks)
{
    predict_body(w, i, 0, marks);
}

static void predict_body(m2c_world *w, int i, int batch, const int *marks)
{
    body *b = &w->b[i];
    w->st.predictions++;
    event ev;
    memset(&ev, 0, sizeof ev);
    ev.t = INFINITY;
    ev.kind = EV_NONE;
    ev.partner = -1;
    if (b->state == ASLEEP) {
        /* asleep: static for the dynamic bodies (they predict against it), but a kinematic
         * body never predicts, so the sleeper watches the kinematic ones itself -- a paddle
         * swept through a ball at rest with no event at all (issue 33) */
        if (w->nkin > 0) {
            best_contact bc;
            memset(&bc, 0, sizeof bc);
            bc.c.t = w->now + horizon(w->now);
            bc.c.rate = -INFINITY;
            bc.c.window = INFINITY;
            bc.partner = -1;
            ev.t = bc.c.t;
            ev.kind = EV_WINDOW;
            for (int k = 0; k < w->nkin; k++)
                visit(w, i, w->kinematic[k], &bc);
            set_contact(w, &ev, &bc);
        }
        b->ev = ev;
        heap_update(w, i);
        return;
    }
    int dx, dy;
    double tc = grid_crossing(w, i, INFINITY, &dx, &dy);
    if (tc < INFINITY) {
        ev.t = w->now + tc;
        ev.kind = EV_CELL;
        ev.dx = dx;
        ev.dy = dy;
    }
    if (b->state == RESTING) {
        if (b->rest_time < ev.t) {
            ev.t = b->rest_time > w->now ? b->rest_time : w->now;
            ev.kind = EV_REST;
        }
        double tl = rest_leave_time(w, i, ev.t - w->now);
        if (w->now + tl < ev.t) {
            ev.t = w->now + tl;
            ev.kind = EV_LEAVE;
        }
    }
    if (!(ev.t < INFINITY)) {
        /* nothing else due: search a finite horizon all the same (the root finder's window
         * rule misses real roots with tmax = inf, issue 33) and predict again at its end */
        ev.t = w->now + horizon(w->now);
        ev.kind = EV_WINDOW;
    }
    /* a body in the contact solver is predicted again at every tick (solver_tick): searching
     * beyond the next one is wasted (in a settled pile, most of a tick's cost) */
    double tick = b->state == SOLVING ? solver_next_tick(w) : INFINITY;
    int capped = tick <= ev.t;
    if (capped) {
        ev.t = tick;
        ev.kind = EV_NONE;
    }
    best_contact bc;
    memset(&bc, 0, sizeof bc);
    bc.c.t = ev.t;
    bc.c.rate = -INFINITY;
    bc.c.window = INFINITY;
    bc.partner = -1;
    bc.batch = batch && b->state == SOLVING;
    bc.marks = marks;
    grid_neighbours(w, i, visit, &bc);
    set_contact(w, &ev, &bc);
    if (capped && ev.kind == EV_NONE)
        ev.t = INFINITY; /* nothing before the tick, which predicts it again */
    b->ev = ev;
    heap_update(w, i);
}

/* A contact with a sensor is reported and passes through; one of a body flagged for the
 * pre-solve goes to the callback first, which may veto it (then it passes through). */
static int passes_through(m2c_world *w, int i, int j, const event *ev)
{
    int flags = w->b[i].flags | w->b[j].flags;
    m2c_event e;
    if (flags & M2C_FLAG_SENSOR) {
        contact_event(w, i, j, ev, M2C_EVENT_SENSOR, &e);
        world_emit(w, &e);
        ghost_add(w, i, j);
        return 1;
    }
    if (!(flags & M2C_FLAG_PRESOLVE) || !w->presolve)
        return 0;
    contact_event(w, i, j, ev, M2C_EVENT_PRESOLVE, &e);
    w->in_presolve = 1;
    int keep = w->presolve(w->presolve_user, &e);
    w->in_presolve = 0;
    if (keep)
        return 0;
    ghost_add(w, i, j);
    return 1;
}

/* A feature crossing of a pair passing through a sensor (ghost k): the shapes' exact signed
 * distance now decides. A crossing out with the shapes touching (within the tolerance) is the
 * leave; any other crossing while they overlap is inside the pair (a rotating corner crossing
 * the sensor's edge while the body straddles it), no event; found clearly apart, they left
 * unseen: the leave now (never seen in the tests; a guard). */
static void sensor_crossing(m2c_world *w, int i, int j, int k, const event *ev)
{
    double tol = w->cfg.tolerance, gap = shape_signed_gap(w, i, j, w->now);
    if (ev->up ? gap >= -tol : gap > tol) {
        ghost_remove_at(w, k);
        m2c_event e;
        contact_event(w, i, j, ev, M2C_EVENT_SENSOR_LEAVE, &e);
        world_emit(w, &e);
    }
}

static void process(m2c_world *w, int i)
{
    event ev = w->b[i].ev;
    w->st.events++;
    switch (ev.kind) {
    case EV_CELL:
        w->st.cell_crossings++;
        grid_move(w, i, ev.dx, ev.dy);
        world_predict(w, i);
        break;
    case EV_CONTACT: {
        int j = ev.partner;
        if (w->b[j].counter != ev.partner_counter) {
            w->st.stale++;
            world_predict(w, i);
            break;
        }
        int g = w->nghosts > 0 ? ghost_find(w, i, j) : -1;
        int in_sensor = g >= 0 && ((w->b[i].flags | w->b[j].flags) & M2C_FLAG_SENSOR);
        if (in_sensor)
            sensor_crossing(w, i, j, g, &ev); /* a leave, or nothing */
        else if (g >= 0)
            ghost_remove_at(w, g); /* they met again: a contact like any other */
        if (in_sensor || passes_through(w, i, j, &ev)) {
            world_predict(w, i);
            if (w->b[j].kind == M2C_DYNAMIC)
                world_predict(w, j);
            break;
        }
        if (w->b[i].state == ASLEEP) { /* a kinematic body reached a sleeper: it wakes */
            int n = wake_island(w, i, w->woken, w->cap);
            for (int k = 0; k < n; k++)
                if (w->woken[k] != i)
                    world_predict(w, w->woken[k]);
        }
        int woken = respond(w, i, j, &ev);
        world_predict(w, i);
        if (w->b[j].kind == M2C_DYNAMIC)
            world_predict(w, j);
        for (int k = 0; k < woken; k++)
            if (w->woken[k] != j)
                world_predict(w, w->woken[k]);
        break;
    }
    case EV_REST: {
        body *b = &w->b[i];
        m2c_event e = {w->now, M2C_EVENT_REST, i, b->support, 0, 0, 0, 0, 0, 0};
        world_emit(w, &e);
        b->rest_time = NAN;
        if (b->sleep_at_rest) {
            fall_asleep(w, i);
        } else {
            w->st.rests++;
            world_predict(w, i);
        }
        break;
    }
    case EV_LEAVE:
        rest_restore(w, i);
        world_predict(w, i);
        break;
    case EV_WINDOW:
        w->st.windows++;
        world_predict(w, i);
        break;
    default:
        w->b[i].ev.t = INFINITY;
        heap_update(w, i);
        break;
    }
}

int m2c_world_step(m2c_world *w, double until, m2c_event *events, int capacity, int *count)
{
    int dummy;
    if (!count)
        count = &dummy;
    *count = 0;
    if (!isfinite(until))
        return fail(w, "the time to step to must be a finite number");
    if (capacity < 4 || !events)
        return fail(w, "the event buffer needs room for at least 4 events");
    if (w->in_presolve)
        return fail(w, "step: no changes inside the pre-solve callback");
    if (w->broken)
        return -1;
    w->out = events;
    w->out_cap = capacity;
    w->out_n = 0;
    if (!w->prepared && prepare(w) != 0)
        return -1;
    /* a call to another time starts a new step (the caller left the last one unfinished: a
     * callback that raised), as one after a step that returned 0 or -1 does */
    if (until != w->step_until) {
        w->step_events = 0;
        w->step_until = until;
    }
    if (flush_pending(w)) {
        *count = w->out_n;
        w->out = NULL;
        return 1;
    }
    long long spent = 0, solves0 = w->st.solves;
    for (;;) {
        int i = heap_top(w);
        double t = i >= 0 ? w->b[i].ev.t : INFINITY;
        double tt = w->ntimers > 0 ? w->timers[0].t : INFINITY;
        double ts = solver_next_tick(w);   /* sustained contact (contact_solver.c) */
        double next = t < tt ? t : tt;
        int tick = ts <= next; /* first at a tie: its solve, not an exact event, takes the
                                  solver's pairs that come back to the slop's depth there */
        if (tick)
            next = ts;
        if (!(next <= until))
            break;
        /* a run of events within STUCK_SPAN (relative) of its first: a ball crushed between a
         * piston and a wall bounces ever faster (Zeno: infinitely many bounces before the
         * crush), a window of a rotation too fast for doubles advances time by nothing, a jam
         * repeats at one instant; 100,000 such events are 10^11 per second of simulated time, a
         * hundred times what a pile of 10^5 bodies settling at one instant reports */
        if (next - w->last_time <= STUCK_SPAN * (1 + fabs(next))) {
            w->same++;
        } else {
            w->same = 0;
            w->last_time = next;
        }
        if (w->same > SAME_TIME_LIMIT) {
            w->out = NULL;
            *count = w->out_n;
            w->step_events = 0;
            w->same = 0;
            snprintf(w->err, sizeof w->err,
                     "stuck: more than 100000 events within 1e-6 s (relative) of t = %.17g (a "
                     "body squeezed between others, or a motion too fast for double precision)",
                     next);
            return -1;
        }
        /* the call's work budget: return to the caller (which calls again) often enough for
         * it to honour signals -- a step of a stuck world would otherwise never come back */
        if (++spent > WORK_EVENTS || w->st.solves - solves0 > WORK_SOLVES) {
            flush_pending(w);
            *count = w->out_n;
            w->out = NULL;
            return 1;
        }
        if (tick) {
            if (next > w->now)
                w->now = next;
            solver_tick(w);
        } else if (w->ntimers > 0 && tt <= t) {
            w->now = tt;
            m2c_event e = {tt, M2C_EVENT_TIMER, w->timers[0].id, -1, 0, 0, 0, 0, 0, 0};
            timer_pop(w);
            world_emit(w, &e);
        } else {
            if (next > w->now)
                w->now = next;
            process(w, i);
        }
        if (w->overflow) { /* response.c refused a non-finite impulse: err says which pair */
            w->overflow = 0;
            w->out = NULL;
            *count = w->out_n;
            w->step_events = 0;
            return -1;
        }
        /* (counted over the resumed calls of one step: each returns when the buffer fills,
         * about every thousand events with the Python binding's buffer; a contact solver's
         * tick is no event: it reports nothing, and there are only until / h of them) */
        if (!tick && w->cfg.max_events > 0 && ++w->step_events > w->cfg.max_events) {
            w->out = NULL;
            *count = w->out_n;
            w->step_events = 0; /* (a failure ends the step: the next call starts one) */
            return fail(w, "the step exceeded max_events");
        }
        /* an event can report up to 4 records: stop while there is room (the caller resumes) */
        if (w->npending > 0 || (w->out_n > 0 && w->out_n + 4 > w->out_cap)) {
            flush_pending(w);
            *count = w->out_n;
            w->out = NULL;
            return 1;
        }
    }
    if (until > w->now)
        w->now = until;
    w->step_events = 0; /* the step is done */
    *count = w->out_n;
    w->out = NULL;
    return 0;
}

int m2c_world_pose(const m2c_world *w, int i, double t, double out[3])
{
    if (i < 0 || i >= w->n || !(t >= w->b[i].m.t))
        return -1;
    snap s = motion_at(&w->b[i].m, t);
    out[0] = s.x;
    out[1] = s.y;
    out[2] = s.th;
    return 0;
}

int m2c_world_velocity(const m2c_world *w, int i, double t, double out[3])
{
    if (i < 0 || i >= w->n || !(t >= w->b[i].m.t))
        return -1;
    snap s = motion_at(&w->b[i].m, t);
    out[0] = s.vx;
    out[1] = s.vy;
    out[2] = s.w;
    return 0;
}

int m2c_world_poses(const m2c_world *w, double t, double *out)
{
    int status = 0;
    for (int i = 0; i < w->n; i++) {
        const motion *m = &w->b[i].m;
        snap s = motion_at(m, t < m->t ? m->t : t);
        if (t < m->t)
            status = -1;
        out[3 * i] = s.x;
        out[3 * i + 1] = s.y;
        out[3 * i + 2] = s.th;
    }
    return status;
}

void m2c_world_motions(const m2c_world *w, double *out, unsigned int *counters)
{
    for (int i = 0; i < w->n; i++) {
        const motion *m = &w->b[i].m;
        double *o = out + 9 * i;
        o[0] = m->t;
        o[1] = m->x;
        o[2] = m->y;
        o[3] = m->th;
        o[4] = m->vx;
        o[5] = m->vy;
        o[6] = m->w;
        o[7] = m->ax;
        o[8] = m->ay;
        counters[i] = w->b[i].counter;
    }
}

double m2c_world_next_time(m2c_world *w)
{
    if (w->broken || (!w->prepared && prepare(w) != 0))
        return INFINITY;
    if (w->npending > 0)
        return w->now;
    int i = heap_top(w);
    double t = i >= 0 ? w->b[i].ev.t : INFINITY;
    double tt = w->ntimers > 0 ? w->timers[0].t : INFINITY;
    /* the contact solver's next tick changes its bodies' motions too: between ticks they fly
     * freely under gravity, so a server that slept past a tick would leave its clients drawing
     * a resting body falling through the floor */
    double ts = solver_next_tick(w);
    double next = t < tt ? t : tt;
    return ts < next ? ts : next;
}

int m2c_world_add_timer(m2c_world *w, double t)
{
    if (!(t >= w->now) || !isfinite(t))
        return fail(w, "a timer must be at a finite time not before now");
    if (w->in_presolve)
        return fail(w, "add_timer: no changes inside the pre-solve callback");
    if (timer_push(w, t, w->next_timer_id) != 0)
        return fail(w, "out of memory");
    return w->next_timer_id++;
}

int m2c_world_cancel_timer(m2c_world *w, int id)
{
    if (timer_remove(w, id) == 0)
        return 0;
    return fail(w, "cancel_timer: no such timer pending");
}

double m2c_world_energy(const m2c_world *w, double t)
{
    double e = 0;
    for (int i = 0; i < w->n; i++) {
        const body *b = &w->b[i];
        if (b->kind != M2C_DYNAMIC)
            continue;
        snap s = motion_at(&b->m, t < b->m.t ? b->m.t : t);
        e += 0.5 * b->mass * (s.vx * s.vx + s.vy * s.vy) + 0.5 * b->inertia * s.w * s.w
             - b->mass * (b->gx * s.x + b->gy * s.y);
    }
    return e;
}

int m2c_world_solving(const m2c_world *w, int i)
{
    return i >= 0 && i < w->n && w->b[i].kind == M2C_DYNAMIC && w->b[i].state == SOLVING;
}

double m2c_world_contact_slop(const m2c_world *w)
{
    return solver_slop(w);
}

int m2c_world_asleep(const m2c_world *w, int i)
{
    return i >= 0 && i < w->n && w->b[i].state == ASLEEP;
}

void m2c_world_stats(const m2c_world *w, m2c_stats *out)
{
    *out = w->st;
}

/* The most rotation windows one first_contact solves before it gives up (and says so). */
#define FIRST_CONTACT_WINDOWS 2000000
#define FIRST_CONTACT_SEARCHES 1000000 /* rotating searches resumed (16 windows each at most) */

int m2c_world_first_contact(m2c_world *w, int i, int j, double tmax, double *t)
{
    if (w->broken || i < 0 || j < 0 || i >= w->n || j >= w->n || i == j || !(tmax > 0)
        || w->b[i].kind == KIND_REMOVED || w->b[j].kind == KIND_REMOVED)
        return fail(w, "first_contact: bad bodies or horizon");
    double now = w->now, end = now + tmax;
    int found = 0;
    long long budget = w->st.windows_solved + FIRST_CONTACT_WINDOWS;
    w->any_kinds = 1;
    for (int guard = 0;; guard++) {
        if (guard >= FIRST_CONTACT_SEARCHES || w->st.windows_solved > budget) {
            /* said, never a silent "no contact" */
            snprintf(w->err, sizeof w->err, "first_contact: gave up at t = %.17g of %.17g (%d "
                     "searches or %d rotation windows solved: a fast orbit over a long horizon)",
                     w->now, end, FIRST_CONTACT_SEARCHES, FIRST_CONTACT_WINDOWS);
            found = -1;
            break;
        }
        contact c;
        memset(&c, 0, sizeof c);
        c.t = end;
        c.rate = -INFINITY;
        c.window = INFINITY;
        predict_pair(w, i, j, &c);
        if (c.window < c.t && c.window < end) { /* a rotating search stopped: go on from there */
            w->now = c.window;
            continue;
        }
        if (c.improved) {
            *t = c.t;
            found = 1;
        }
        break;
    }
    w->any_kinds = 0;
    w->now = now;
    return found;
}
