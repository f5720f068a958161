/*
 * engine.h -- the engine's internal data: flat arrays, no allocation per event.
 *
 * Each dynamic body holds exactly one pending event (its earliest: a contact, a cell
 * crossing, the end of a prediction window, ...) in an indexed binary heap keyed by
 * (time, body id). An event with a partner remembers the partner's motion counter; the
 * counter changes whenever the partner's motion does, so a stale event is recognised when it
 * is popped and the body is predicted again (Rapaport 1980; Lubachevsky 1991). Static and
 * kinematic bodies never change motion and hold no event: the dynamic body of each pair
 * predicts the pair.
 */
#ifndef M2C_ENGINE_INTERNAL_H
#define M2C_ENGINE_INTERNAL_H
/* A moving (dynamic or kinematic) body's vertices, all its parts together. Why a limit: the
 * prediction of one pair of turning bodies compares every vertex of each with every edge of
 * the other in one go, and returns to the caller (who honours signals) only after it: two
 * turning 128-gons take 0.7 s, two 512-gons 11 s, two rings of 256 octagons 33 s (2026-12-07,
 * bench/turning_pairs.py).
 * Box2D allows 8 vertices a polygon; a static body may have far more (only moving ones pair). */
#define MAX_MOVING_VERTICES 128

#include <stddef.h>
#include <stdint.h>

#include "max2code_engine.h"

/* A body's motion from its own reference time t: every point of the body is at
 * (x, y) + (vx, vy) s + (ax, ay) s^2/2 + R(th + w s) offset, s = time - t. */
typedef struct {
    double t;
    double x, y, vx, vy, ax, ay;
    double th, w;
    double c, s;                /* cos th, sin th (kept: most bodies never turn) */
} motion;

/* The same motion evaluated at one time (a snapshot, never stored as the reference). */
typedef struct {
    double x, y, vx, vy, ax, ay;
    double th, w, c, s;     /* angle, angular velocity, cos and sin of the angle */
} snap;

enum { EV_NONE = 0, EV_CONTACT, EV_CELL, EV_WINDOW, EV_REST, EV_LEAVE };
/* EV_REST: a resting body's bounce series ends (reported; asleep from then on if it sleeps);
 * EV_LEAVE: a body sliding on an edge reaches its end. */
/* Contact features: a point (vertex + rounding radius) of each body (PP), a point of the
 * body against an edge of the partner (PL), an edge of the body against a point of the
 * partner (LP). */
enum { F_PP = 0, F_PL = 1, F_LP = 2 };

typedef struct {
    double t;
    int kind;
    int partner;
    uint32_t partner_counter;
    int feature, fa, fb, side;  /* contact: feature kind, vertex/edge indices, side of the edge */
    int up;                     /* contact: the gap rises through 0 (a sensor pair's way out) */
    int dx, dy;                 /* cell crossing: the step to the next cell */
} event;

/* One convex part of a body's shape: vertices w->verts[2 (vert + k)], k < nvert (absolute
 * indices), rounded by radius. A single-shape body has one part; a compound body several,
 * their vertices one after another from the body's first vertex. */
typedef struct {
    int vert, nvert;
    double radius;
} part;

enum { AWAKE = 0, RESTING = 1, ASLEEP = 2, SOLVING = 3 };
/* SOLVING: in sustained contact, moved by the contact solver (contact_solver.c) */

/* A removed body's kind: in no list, no cell, no heap; nothing predicts against it. */
#define KIND_REMOVED 3
#define DEF_COOKIE 0x6d32635f /* "m2c_": m2c_default_body_def() made the def */

typedef struct {
    motion m;
    int kind;                   /* M2C_STATIC / M2C_KINEMATIC / M2C_DYNAMIC */
    double inv_mass, inv_inertia, mass, inertia;
    double restitution, radius, friction;
    double bound;               /* max |offset| + radius: a circle about the reference point */
    double rho;                 /* max |offset| (what rotation moves) */
    int nvert, vert;            /* vertices: w->verts[2 (vert + k)], k < nvert (all parts) */
    int part, nparts;           /* its parts: w->parts[part + k], k < nparts (1: one shape;
                                   radius is then the shape's, else the first part's). Contact
                                   features name vertices and edges by body-level index (from
                                   vert), whichever part they are in */
    int group;
    unsigned int category, mask; /* collision filter (max2code_engine.h) */
    int flags;                  /* M2C_FLAG_* */
    double dmass, dinertia;     /* mass and inertia kept for becoming dynamic (0: none given) */
    uint32_t counter;           /* bumped whenever the motion changes */
    int cx, cy;                 /* cell (dynamic bodies) */
    int next, prev;             /* the cell's list of dynamic bodies */
    double gx, gy;              /* its own gravity (m.ax, m.ay differ while it rests) */
    int state;                  /* AWAKE, RESTING, ASLEEP (the rest rule, rest.c) */
    int support, support_edge;  /* RESTING: the body and edge it slides on */
    int sleep_at_rest;          /* RESTING: fall asleep at rest_time */
    double support_n[2];        /* RESTING: the edge's normal towards the body */
    double rest_time;           /* RESTING: when the bounce series ends (reported then) */
    double last_contact;        /* time of its last collision (the collapse rule) */
    int burst;                  /* collisions in a row, each within t_c of the last */
    int elastic;                /* its burst's cluster rests on nothing: rule 2 applies */
    int instant;                /* collisions in a row at one identical time (rule 5) */
    event ev;
} body;

typedef struct {
    double x0, y0, size;
    int nx, ny;
    int *head;                  /* per cell: first dynamic body in it, or -1 */
    int *fixed_start;           /* per cell: static bodies within reach (CSR into fixed) */
    int *fixed;
} grid;

typedef struct {
    double t;
    int id;
} timer;

typedef struct {
    int a, b;                   /* a < b */
} pair;

struct m2c_world {
    m2c_config cfg;
    double now;
    body *b;
    int n, cap;
    double *verts;              /* body-frame vertices, 2 per vertex */
    double *edges;              /* per vertex k: unit direction and length of edge k -> k+1 */
    int nverts, capverts;
    part *parts;                /* every body's parts (engine.h: part) */
    int nparts, capparts;
    int *heap, *heap_pos;       /* indexed heap of dynamic bodies */
    int heap_n;
    int *kinematic;             /* kinematic bodies: every dynamic body checks them */
    int *stack, *woken, *members;   /* scratch (waking a pile, freezing a cluster) */
    int nkin;
    grid g;
    int prepared;
    int broken;                 /* the generated headers do not match (see err) */
    int any_kinds;              /* m2c_world_first_contact: predict pairs of any kinds */
    int any_sensor;             /* a body was ever added as a sensor (add_body checks overlaps) */
    long long same;             /* events in a row at one identical time (a guard) */
    long long step_events;      /* events of the step under way, its resumed calls included */
    double step_until;          /* the time that step goes to */
    double last_time;
    double bound_max;           /* largest bound of a dynamic body */
    timer *timers;
    int ntimers, captimers, next_timer_id;
    m2c_event *out;             /* the step's output buffer */
    int out_n, out_cap;
    m2c_event *pending;         /* reported events that did not fit: given out first */
    int npending, cappending;
    pair *ghosts;               /* pairs passing through each other (vetoed, sensors) */
    int nghosts, capghosts;
    m2c_presolve_fn presolve;
    void *presolve_user;
    int in_presolve;            /* inside the pre-solve callback: no changes allowed */
    m2c_stats st;
    struct solver *solver;      /* sustained contact (contact_solver.c); NULL until used */
    int overflow;               /* an impulse beyond doubles was refused: the step fails (err) */
    char err[256];
};

/* motion.c */
snap motion_at(const motion *m, double t);
void body_commit(body *b, double t);        /* make time t the body's reference time */
void world_point(const snap *s, const double off[2], double out[2]);  /* s + R off */
void world_vector(const snap *s, const double v[2], double out[2]);   /* R v */

/* timers.c: a min-heap of (time, id); w->timers[0] is the next one due */
int timer_push(m2c_world *w, double t, int id);
void timer_pop(m2c_world *w);
int timer_remove(m2c_world *w, int id);   /* 0, or -1 when no such timer is pending */

/* heap.c */
int heap_init(m2c_world *w, int capacity);
void heap_insert(m2c_world *w, int i);
void heap_update(m2c_world *w, int i);      /* after b[i].ev.t changed */
int heap_top(const m2c_world *w);           /* -1 when empty */
void heap_remove(m2c_world *w, int i);

/* grid.c */
int grid_build(m2c_world *w);
void grid_free(grid *g);
void grid_cell_of(const grid *g, double x, double y, int *cx, int *cy);
void grid_insert(m2c_world *w, int i);
void grid_move(m2c_world *w, int i, int dx, int dy);
void grid_remove(m2c_world *w, int i);      /* a dynamic body leaves its cell's list */
double grid_crossing(const m2c_world *w, int i, double tmax, int *dx, int *dy);
/* Calls visit(w, i, j, ctx) for every body j that may touch dynamic body i before it
 * leaves its cell: dynamic bodies of the 3x3 cells around it, static bodies within reach
 * of its cell, every kinematic body. */
typedef void (*visit_fn)(m2c_world *w, int i, int j, void *ctx);
void grid_neighbours(m2c_world *w, int i, visit_fn visit, void *ctx);

/* predict.c */
typedef struct {
    double t;                   /* absolute time */
    double rate;                /* how fast the gap closes then (ties: the fastest first) */
    int feature, fa, fb, side;
    int improved;               /* set when predict_pair found a better one */
    int up;                     /* the gap rises through 0 there (only for a sensor's ghost) */
    double window;              /* rotation searched only up to here (then predict again) */
} contact;
int predict_check_generated(m2c_world *w);
/* The earliest contact of bodies i (dynamic) and j at a time in (now, now + tmax]; 1 and
 * *c if there is one before *the current best* (c->t on entry), else 0. */
int predict_pair(m2c_world *w, int i, int j, contact *c);
/* The second time derivative of the event's gap now (relative acceleration and rotation);
 * *rotates (if not NULL): whether rotation moves either feature. */
double contact_gap_accel(m2c_world *w, int i, int j, const event *ev, int *rotates);

/* response.c */
int respond(m2c_world *w, int i, int j, const event *ev);
void contact_geometry(const m2c_world *w, int i, int j, const event *ev, double n[2], double p[2]);
void contact_event(const m2c_world *w, int i, int j, const event *ev, int kind, m2c_event *out);
int part_frame_still(const body *B);
double pair_energy(const m2c_world *w, const body *A, const body *B, int free_b);
int part_within_energy(const m2c_world *w, body *A, body *B, int free_b, const double n[2],
                       const double ra[2], const double rb[2], double target);
#define M2C_EVENT_PRESOLVE 0 /* (internal: the kind of the event handed to the pre-solve) */

#define BURST 16 /* collisions in a row, each within t_c of the last: rules 2 and 4 of rest.c */
#define INSTANT 64 /* collisions in a row at one instant: rule 5 of rest.c */

/* rest.c: the rest rule and the inelastic-collapse rule (README: "The rest rule") */
double rest_speed(const m2c_world *w, double gn);
double collapse_time(const m2c_world *w);
double wake_speed(const m2c_world *w, const body *b);
int rest_after_contact(m2c_world *w, int k, int s, const event *ev, int k_is_a, double e);
int wake_island(m2c_world *w, int i, int *woken, int cap);
void rest_restore(m2c_world *w, int k);
int body_still(const body *b);
void fall_asleep(m2c_world *w, int k);
void rest_burst(m2c_world *w, int k);
double rest_leave_time(const m2c_world *w, int k, double tmax);

/* contact_solver.c: sustained contact (docs/engine-contact.md) */
double solver_step(const m2c_world *w);                 /* h; < 0: off */
double solver_soft_speed(const m2c_world *w, const body *b);  /* slower contacts join */
double solver_slop(const m2c_world *w);                 /* overlap its pairs may keep; 0: off */
int solver_in_cone(const m2c_world *w, const body *B, const snap *sn, int v, const double d[2]);
#define SOLVER_CONE_SLACK 0.05  /* solver_in_cone: a sine */
int solver_adopt(m2c_world *w, int k);                  /* 1 when k joined */
int solver_has(const m2c_world *w, int i);
int solver_count(const m2c_world *w);                   /* bodies in it */
double solver_next_tick(const m2c_world *w);            /* INFINITY when no body is in it */
void solver_tick(m2c_world *w);
void solver_free(m2c_world *w);
void solver_forget(m2c_world *w, int k);                /* k flies again (an edit) */
void solver_save(const m2c_world *w, void (*put)(void *, const void *, size_t), void *ctx);
int solver_load(m2c_world *w, int (*get)(void *, void *, size_t), void *ctx);  /* 0 or -1 */
void solver_wedged(m2c_world *w, int k);
int centred_circle(const m2c_world *w, const body *B);  /* no torque from a normal impulse */
int solver_rest_at_once(m2c_world *w, int i, int j);     /* put to sleep at once */
int solver_soft_response(m2c_world *w, int i, int j, const event *ev, double closing, int pair_only,
                         m2c_event *out, int *moved, int cap,
                         int *nmoved);  /* moved: solver neighbours changed */

/* motion.c */
double first_crossing(double x, double v, double a, double edge, int dir, double tmax);

/* geometry.c: shapes at the world's current time */
/* Gap between the shapes of bodies i and j (radii included): negative when they overlap
 * (a vertex inside the other polygon or crossing edges count as overlapping). */
double shape_gap(const m2c_world *w, int i, int j);
/* The signed distance between the shapes of bodies i and j at time t (radii included):
 * negative by the penetration depth when they overlap (separating axes). */
double shape_signed_gap(const m2c_world *w, int i, int j, double t);
/* 1 when the pair may collide: different groups (or none), each category in the other's mask. */
int pair_filtered(const body *a, const body *b);

/* ghost.c: pairs that pass through each other until they meet again */
int ghost_find(const m2c_world *w, int i, int j);   /* its index, or -1 */
int ghost_add(m2c_world *w, int i, int j);
void ghost_remove_at(m2c_world *w, int k);
void ghost_forget(m2c_world *w, int i);              /* every pair of a removed body */
void ghost_leave_sensors(m2c_world *w, int i);      /* moved: its sensor pairs end now */
void ghost_enter_sensors(m2c_world *w, int i);      /* added: the sensors it overlaps, now */

/* geometry.c: a body's parts */
/* Part k of body b as a body of its own: the same motion, kind and state, with the part's
 * vertices and radius (the shape code written for one shape runs on it unchanged). */
body part_view(const m2c_world *w, const body *b, int k);
/* The part of body b holding its vertex v (a body-level index), and that part's radius. */
int vertex_part(const m2c_world *w, const body *b, int v);
double vertex_radius(const m2c_world *w, const body *b, int v);
/* rho (max |offset|) and bound (max |offset| + the part's radius) of a body from its parts. */
void body_reach(const m2c_world *w, body *b);

/* world.c */
/* Why a body of `kind` with `nvertices` cannot be added or made so (MAX_MOVING_VERTICES), or
 * NULL: one rule and one message for add_body and set_kind. */
const char *moving_vertices_refusal(int kind, long long nvertices);
void world_predict(m2c_world *w, int i);
void world_predict_solver(m2c_world *w, int i); /* the tick: a pair of solver bodies once */
void world_predict_marked(m2c_world *w, int i, const int *marks); /* a marked set: once */
int world_emit(m2c_world *w, const m2c_event *e);

#endif
