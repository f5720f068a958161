/*
 * max2code_engine.h -- the predictive (event-driven) 2D engine: public C API.
 *
 * A world holds rigid bodies whose every point moves as
 *     c + v t + a t^2/2 + R(angle + omega t) offset
 * between events. Time jumps from one predicted event to the next: contacts happen at their
 * exact (predicted) times, nothing is integrated between events, and a body's state is kept
 * at its own last event time (poses at any later time are evaluated exactly on request).
 *
 * Shapes: every body has a list of vertices in its own frame (offsets from its reference
 * point, which for a dynamic body is its centre of mass) and a rounding radius:
 *     1 vertex            a circle (radius > 0)
 *     2 vertices          a segment (radius 0: a thin two-sided wall) or a capsule (radius > 0)
 *     3 or more vertices  a convex polygon, anticlockwise (radius > 0 rounds its corners)
 * A compound body has several such shapes (parts: circles, segments, capsules, convex
 * polygons, each with its own radius) on one rigid body: m2c_body_def.parts.
 * Static bodies never move; kinematic bodies follow their prescribed motion forever (the
 * paper's orbiting paddles); both have infinite mass. Dynamic bodies respond to impulses.
 *
 * Everything between the cdef markers is read by the Python binding (cffi, ABI mode):
 * plain declarations only there (the binding drops the M2C_API markers).
 *
 * Only the functions marked M2C_API are exported from the shared library (it is built with
 * -fvisibility=hidden): the engine's internals and the root-finding runtime stay private.
 */
#ifndef MAX2CODE_ENGINE_H
#define MAX2CODE_ENGINE_H

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32)
#define M2C_API __declspec(dllexport)
#else
#define M2C_API __attribute__((visibility("default")))
#endif

/* cdef-begin */
typedef struct m2c_world m2c_world;

enum {
    M2C_STATIC = 0,
    M2C_KINEMATIC = 1,
    M2C_DYNAMIC = 2
};

/* Event kinds reported by m2c_world_step. */
enum {
    M2C_EVENT_COLLISION = 1,   /* an impulse between a and b */
    M2C_EVENT_REST = 2,        /* a came to rest on b (the rest rule; time = the analytic limit) */
    M2C_EVENT_WAKE = 3,        /* a, asleep, was woken (hit by b) */
    M2C_EVENT_TIMER = 4,       /* a timer set with m2c_world_add_timer fired (a = its id) */
    M2C_EVENT_SENSOR = 5,      /* a started to overlap sensor b (or b a sensor a): no response;
                                  a body added overlapping a sensor enters it then */
    M2C_EVENT_SEPARATE = 6,    /* a, resting or sliding on b (the rest rule), left it; only
                                  with M2C_FLAG_SEPARATE on a or b (a bounce is its own end) */
    M2C_EVENT_SENSOR_LEAVE = 7 /* a and sensor b (or b and sensor a) stopped overlapping: once
                                  per M2C_EVENT_SENSOR, at the exact time; at once when either
                                  is moved away (m2c_world_set_pose); none when either is
                                  removed (m2c_world_remove_body) while they overlap */
};

/* Body flags (m2c_body_def.flags, m2c_world_set_flags). */
enum {
    M2C_FLAG_SENSOR = 1,       /* reports contacts (M2C_EVENT_SENSOR) and never responds */
    M2C_FLAG_PRESOLVE = 2,     /* its contacts go to the pre-solve callback first */
    M2C_FLAG_SEPARATE = 4      /* report M2C_EVENT_SEPARATE when it leaves a sustained contact
                                  (or something resting on it leaves it) */
};

/* One convex part of a compound body (m2c_body_def.parts): its vertices in the body frame and
 * its rounding radius, as a single-shape body's (1: circle, 2: segment/capsule, >= 3 polygon). */
typedef struct {
    int nvertices;
    const double *vertices;    /* 2 * nvertices numbers */
    double radius;
} m2c_part;

typedef struct {
    int kind;                  /* M2C_STATIC, M2C_KINEMATIC or M2C_DYNAMIC */
    double x, y, angle;        /* reference point and angle at the world's current time */
    double vx, vy, omega;      /* velocity and angular velocity */
    double ax, ay;             /* constant acceleration (gravity) */
    double mass, inertia;      /* dynamic bodies: both > 0 */
    double restitution;        /* 0..1; a contact uses the product of the two */
    double radius;             /* rounding radius (the circle's radius) */
    int nvertices;             /* 1: circle, 2: segment/capsule, >= 3: convex polygon
                                  (at most 1 << 24 a body, all parts together; a dynamic
                                  or kinematic body at most 128: the prediction of two
                                  turning bodies pairs every vertex with every edge) */
    const double *vertices;    /* 2 * nvertices numbers: offsets in the body frame */
    int group;                 /* >= 0: bodies of one group never collide with each other; -1: none */
    double friction;           /* Coulomb coefficient >= 0; a contact uses sqrt(fa fb); impacts only */
    unsigned int category;     /* the body's category bits (default 1) */
    unsigned int mask;         /* the categories it collides with (default all): a pair collides
                                  when each one's category meets the other's mask */
    int flags;                 /* M2C_FLAG_* (default 0) */
    int nparts;                /* a compound body: nparts >= 1 parts (then nvertices 0, vertices
                                  NULL and radius 0: the shape is the parts'); default 0. Its
                                  contacts are its parts' (the earliest part pair's); mass and
                                  inertia are the whole body's, about its reference point */
    const m2c_part *parts;
    int internal;              /* set by m2c_default_body_def(): a def not made by it is refused */
} m2c_body_def;

typedef struct {
    double tolerance;          /* lengths: contact slack, Taylor remainder budget (> 0) */
    double cell_size;          /* broad-phase cell width; 0: chosen from the bodies; < 0: one cell */
    double rest_speed;         /* v_r of the rest rule (README): 0 automatic, < 0 off */
    double collapse_time;      /* t_c of the collapse rules: 0 automatic (1e-3 s), < 0 off */
    long long max_events;      /* a step (m2c_world_step) processing more events than this fails (0: no limit) */
    double contact_step;       /* h of the sustained-contact solver (> 0, e.g. 1/240 s, the Python World's and scene files' default); 0: off */
} m2c_config;

typedef struct {
    double time;
    int kind;                  /* M2C_EVENT_* */
    int a, b;                  /* bodies (b = -1 when none) */
    double nx, ny;             /* contact normal, from a towards b */
    double px, py;             /* contact point */
    double speed;              /* closing speed along the normal before the response */
    double impulse;            /* normal impulse applied (to b; -impulse to a) */
} m2c_event;

typedef struct {
    long long events;          /* popped from the queue (all kinds) */
    long long collisions;      /* impulses applied */
    long long cell_crossings;
    long long windows;         /* window-end events (a rotating search resumed) */
    long long windows_solved;  /* rotating-model windows solved (Taylor models) */
    long long stale;           /* events found stale when popped (partner changed) */
    long long predictions;     /* bodies predicted */
    long long pair_tests;      /* pairs examined */
    long long solves;          /* polynomial root solves */
    long long solves_by_degree[17];
    long long rests, wakes;
    int ncells_x, ncells_y;
    double cell_size;
    long long solver_ticks;    /* contact solver steps */
    long long solver_iterations;   /* its Gauss-Seidel sweeps */
    long long certificates;    /* islands put to sleep with a certificate */
} m2c_stats;

/* A body def with every field at its default: dynamic, at the origin, at rest, mass 1 and
 * inertia 1, restitution 1, no friction, no group (-1), category 1, mask all; no shape (give
 * nvertices, vertices and radius). Start every def from it: a def made otherwise (a zeroed
 * struct) is refused by m2c_world_add_body. */
M2C_API m2c_body_def m2c_default_body_def(void);

M2C_API m2c_world *m2c_world_new(const m2c_config *config);
M2C_API void m2c_world_free(m2c_world *w);

/* The id of the new body (0, 1, ...), or -1 (m2c_world_error says why). */
M2C_API int m2c_world_add_body(m2c_world *w, const m2c_body_def *def);
M2C_API int m2c_world_body_count(const m2c_world *w);

/* Process every event up to time `until` (inclusive, finite), writing reported events to
 * events[0..capacity). Returns 0 when the world reached `until`; 1 when the buffer filled up
 * first, or the call's work budget (some 4,000 events or 2 million root solves) ran out
 * (the world's time is that of the last event processed; *count may be 0: call again -- a
 * caller can honour signals between calls); -1 on error (a world stuck at one instant, more
 * than 100,000 events within 1e-6 (1 + |t|) s of one time t, is an error too).  A
 * step is one call that returns 0 or -1 and the calls to the same `until` before it that
 * returned 1: max_events counts the events of the whole step. */
M2C_API int m2c_world_step(m2c_world *w, double until, m2c_event *events, int capacity, int *count);
M2C_API double m2c_world_time(const m2c_world *w);

/* Pose (x, y, angle) and velocity (vx, vy, omega) of a body at time t >= the body's last
 * event (usually the world's time): exact evaluation, the state is not changed. 0 or -1. */
M2C_API int m2c_world_pose(const m2c_world *w, int body, double t, double out[3]);
M2C_API int m2c_world_velocity(const m2c_world *w, int body, double t, double out[3]);
/* All bodies at once: out[3 i .. 3 i + 2] = pose of body i at time t. */
M2C_API int m2c_world_poses(const m2c_world *w, double t, double *out);
/* Every body's motion segment as the engine holds it, for a client that draws on its own
 * (max2code serve): out[9 i ..] = t0, x, y, angle, vx, vy, omega, ax, ay, the pose at time t
 * being (x, y) + (vx, vy) s + (ax, ay) s^2/2 and angle + omega s, s = t - t0; counters[i]
 * changes whenever body i's motion does (an impulse, rest, wake, input), and only then. */
M2C_API void m2c_world_motions(const m2c_world *w, double *out, unsigned int *counters);
/* The time of the earliest queued event, reported or internal (a cell crossing, the end of a
 * prediction window): no reported event comes before it. INFINITY when nothing is queued. */
M2C_API double m2c_world_next_time(m2c_world *w);

/* Changes at the world's current time (input events; also from inside a step's callbacks,
 * between two calls of m2c_world_step). Each returns 0, or -1 (m2c_world_error says why) and
 * changes nothing. The change is effective at once: every prediction that depends on the body
 * is made again (a kinematic or static body's change predicts every dynamic body again), and
 * bodies resting on it or asleep against it wake. */

/* Remove a body: it takes part in nothing from now on (its id is never reused; its pose
 * stays where it was removed). */
M2C_API int m2c_world_remove_body(m2c_world *w, int body);
/* 1 while the body exists (added and not removed), else 0. */
M2C_API int m2c_world_body_alive(const m2c_world *w, int body);
/* Velocity and angular velocity of a dynamic or kinematic body (static bodies never move). */
M2C_API int m2c_world_set_velocity(m2c_world *w, int body, double vx, double vy, double omega);
/* Move a body (any kind) to a new pose. Refused, naming the other body, when its shape would
 * overlap (deeper than the tolerance) a body it can collide with: no push-out is invented. */
M2C_API int m2c_world_set_pose(m2c_world *w, int body, double x, double y, double angle);
/* Constant acceleration (the body's own gravity) of a dynamic or kinematic body. */
M2C_API int m2c_world_set_acceleration(m2c_world *w, int body, double ax, double ay);
/* Mass and moment of inertia (> 0) about the centre of mass (cx, cy), an offset in the body's
 * frame: the body's reference point moves there (its vertices with it, so the shape stays in
 * place; m2c_world_vertices reads them). Any kind of body: a static or kinematic body keeps
 * them for when it becomes dynamic. */
M2C_API int m2c_world_set_mass(m2c_world *w, int body, double mass, double inertia, double cx,
                               double cy);
/* Change a body's kind (M2C_STATIC, M2C_KINEMATIC, M2C_DYNAMIC). Becoming dynamic needs a mass
 * (given when it was added, or m2c_world_set_mass); becoming static stops it. */
M2C_API int m2c_world_set_kind(m2c_world *w, int body, int kind);
/* An impulse (jx, jy) applied at the world point (px, py) to a dynamic body. */
M2C_API int m2c_world_apply_impulse(m2c_world *w, int body, double jx, double jy, double px,
                                    double py);
/* The body's vertices in its own frame (2 * count numbers, count = its number of vertices --
 * a compound body's parts' one after another, in the parts' order; they change when
 * m2c_world_set_mass moves the reference point): the count, or -1. */
M2C_API int m2c_world_vertices(const m2c_world *w, int body, double *out, int capacity);

/* A body's parts (1 for a single shape): their count, or -1; counts[k] and radii[k] (k <
 * capacity) get part k's number of vertices and rounding radius (its vertices are the next
 * counts[k] of m2c_world_vertices); either may be NULL (not wanted). */
M2C_API int m2c_world_parts(const m2c_world *w, int body, int *counts, double *radii,
                            int capacity);

/* A body's flags (M2C_FLAG_*), from now on. */
M2C_API int m2c_world_set_flags(m2c_world *w, int body, int flags);

/* The pre-solve callback: called with a contact of a body flagged M2C_FLAG_PRESOLVE before its
 * response (the event's normal, point and closing speed filled, impulse 0), at the contact's
 * time. Returning 0 vetoes it: no impulse, and the pair passes through each other until they
 * meet again (a new contact of the pair after they parted or crossed: a one-way platform).
 * It may read the world but not change it (changes fail inside it). */
typedef int (*m2c_presolve_fn)(void *user, const m2c_event *contact);
M2C_API void m2c_world_set_presolve(m2c_world *w, m2c_presolve_fn fn, void *user);

/* A timer: an M2C_EVENT_TIMER event (a = the returned id) at time t. */
M2C_API int m2c_world_add_timer(m2c_world *w, double t);
/* Cancel a pending timer: 0, or -1 when no timer with that id is pending (fired or cancelled). */
M2C_API int m2c_world_cancel_timer(m2c_world *w, int id);

/* The first contact of bodies i and j alone, as if nothing else existed and nothing changed,
 * in (now, now + tmax] (any kinds of body): 1 and *t (absolute), 0 when none, -1 with the
 * error set when the search gave up (two million rotation windows: a fast orbit over a long
 * horizon) -- never a silent 0. The prediction the event loop uses (`max2code scene` shows
 * it per pair). */
M2C_API int m2c_world_first_contact(m2c_world *w, int i, int j, double tmax, double *t);

/* Queries at time t >= now (each body where its motion puts it then; nothing changes). Only
 * bodies whose category meets `mask` are seen (~0u: all). Point and box: the ids of the bodies
 * whose shape contains the point or meets the box go to out[0..capacity); the return value is
 * how many there are (more than capacity: call again with more room), or -1. */
M2C_API int m2c_world_query_point(m2c_world *w, double t, double x, double y, unsigned int mask,
                                  int *out, int capacity);
M2C_API int m2c_world_query_box(m2c_world *w, double t, double x0, double y0, double x1,
                                double y1, unsigned int mask, int *out, int capacity);
/* The first shape the segment from (x0, y0) to (x1, y1) enters at time t: 1 with the fraction
 * of the segment travelled, the body and the surface normal there; 0 when it hits nothing; -1.
 * Exact: the smallest root of each feature's crossing (quadratics for rounded corners and
 * circles, lines for edges). A shape containing the start is not hit (as Box2D). */
M2C_API int m2c_world_cast_ray(m2c_world *w, double t, double x0, double y0, double x1,
                               double y1, unsigned int mask, double *fraction, int *body,
                               double normal[2]);

/* Snapshots (rollback, planning, pickle): m2c_world_save writes the world's whole state to
 * buf (when capacity allows) and returns its size in bytes (call with capacity 0 to learn it);
 * m2c_world_load makes a world from such bytes that goes on exactly as the saved one would
 * (the same future events, bit for bit), or NULL for bytes it cannot take (another library
 * build's, truncated, inconsistent). The pre-solve callback is not saved. */
M2C_API long long m2c_world_save(const m2c_world *w, void *buf, long long capacity);
M2C_API m2c_world *m2c_world_load(const void *buf, long long size);

/* Energy: kinetic + potential (-m a.x) of the dynamic bodies at time t. */
M2C_API double m2c_world_energy(const m2c_world *w, double t);
/* 1 when the body is asleep (the rest rule), else 0. */
M2C_API int m2c_world_asleep(const m2c_world *w, int body);

M2C_API void m2c_world_stats(const m2c_world *w, m2c_stats *out);
/* The sleep certificate of asleep body i's island (the asleep bodies touching it, transitively):
 * 1 when non-negative contact forces inside the friction cones balance every weight and torque
 * (*residual: the worst unbalanced force / weight), 0 when none was found, -1: not asleep. */
M2C_API int m2c_world_certificate(m2c_world *w, int body, double *residual);
/* 1 while the body is moved by the contact solver (sustained contact), else 0. */
M2C_API int m2c_world_solving(const m2c_world *w, int body);
/* The overlap a pair held by the contact solver may keep (its exact events come beyond it):
 * 10,000 tolerances with the solver on, else 0 (docs/engine-contact.md). */
M2C_API double m2c_world_contact_slop(const m2c_world *w);
M2C_API const char *m2c_world_error(const m2c_world *w);
/* cdef-end */

#ifdef __cplusplus
}
#endif

#endif /* MAX2CODE_ENGINE_H */
