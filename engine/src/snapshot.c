/* snapshot.c -- a world's whole state as bytes, and a world made from them: rollback,
 * planning, pickle. Everything is saved as it is (bodies with their pending events, the queue,
 * the broad phase's cells, timers, ghost pairs, undelivered events, counters), so a restored
 * world goes on exactly as the original would: the same future events, bit for bit.
 *
 * The format is this build's memory layout behind a header of sizes: a snapshot is read back
 * by the same library build (anything else is refused, as is any count or index out of range).
 * The pre-solve callback is not saved (give it again). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine.h"

#define MAGIC 0x4d324357u /* "M2CW" */
#define VERSION 4u /* 2: the contact solver's state; 3: bodies' parts (compound bodies); 4: the
                           solver's soft contacts of the instant */

typedef struct {
    uint32_t magic, version, body_size, event_size, timer_size, world_size;
    int32_t n, nverts, nparts, nkin, heap_n, ntimers, nghosts, npending, ncells, nfixed;
} header;

typedef struct {
    char *p;
    size_t used, cap;
} writer;

static void put(writer *w, const void *src, size_t size)
{
    if (size && w->p && w->used + size <= w->cap) /* (no memcpy of an empty array: NULL) */
        memcpy(w->p + w->used, src, size);
    w->used += size;
}

static void put_any(void *ctx, const void *src, size_t size)
{
    put(ctx, src, size);
}

static int ncells(const m2c_world *w)
{
    return w->g.head ? w->g.nx * w->g.ny : 0;
}

long long m2c_world_save(const m2c_world *w, void *buf, long long capacity)
{
    int nc = ncells(w);
    header h = {MAGIC, VERSION, sizeof(body), sizeof(m2c_event), sizeof(timer), sizeof(m2c_world),
                w->n, w->nverts, w->nparts, w->nkin, w->heap_n, w->ntimers, w->nghosts, w->npending, nc,
                nc ? w->g.fixed_start[nc] : 0};
    writer out = {buf, 0, capacity > 0 ? (size_t)capacity : 0};
    put(&out, &h, sizeof h);
    put(&out, w, sizeof *w); /* the scalars (its pointers are replaced when loading) */
    put(&out, w->b, sizeof(body) * (size_t)w->n);
    put(&out, w->verts, sizeof(double) * 2 * (size_t)w->nverts);
    put(&out, w->edges, sizeof(double) * 3 * (size_t)w->nverts);
    put(&out, w->parts, sizeof(part) * (size_t)w->nparts);
    put(&out, w->kinematic, sizeof(int) * (size_t)w->nkin);
    put(&out, w->heap, sizeof(int) * (size_t)w->heap_n);
    put(&out, w->heap_pos, sizeof(int) * (size_t)w->n);
    put(&out, w->timers, sizeof(timer) * (size_t)w->ntimers);
    put(&out, w->ghosts, sizeof(pair) * (size_t)w->nghosts);
    put(&out, w->pending, sizeof(m2c_event) * (size_t)w->npending);
    if (nc) {
        put(&out, w->g.head, sizeof(int) * (size_t)nc);
        put(&out, w->g.fixed_start, sizeof(int) * (size_t)(nc + 1));
        put(&out, w->g.fixed, sizeof(int) * (size_t)h.nfixed);
    }
    solver_save(w, put_any, &out);
    return (long long)out.used;
}

typedef struct {
    const char *p;
    size_t at, size;
} reader;

/* A copy of the next `size` bytes (at least one byte allocated), or NULL when short. */
static void *take(reader *r, size_t size)
{
    if (size > r->size - r->at)
        return NULL;
    void *dst = malloc(size ? size : 1);
    if (dst) {
        memcpy(dst, r->p + r->at, size);
        r->at += size;
    }
    return dst;
}

/* The next `size` bytes into dst: 0, or -1 when short. */
static int get_into(void *ctx, void *dst, size_t size)
{
    reader *r = ctx;
    if (size > r->size - r->at)
        return -1;
    memcpy(dst, r->p + r->at, size);
    r->at += size;
    return 0;
}

/* Every body the contact solver moves is in its list, and no other. */
static int solver_consistent(const m2c_world *w)
{
    int solving = 0;
    for (int i = 0; i < w->n; i++)
        solving += w->b[i].kind == M2C_DYNAMIC && w->b[i].state == SOLVING;
    return solving == 0 || (w->solver && solver_next_tick(w) < INFINITY
                            && solving == solver_count(w));
}

static int in_range(int v, int lo, int hi) /* lo <= v < hi */
{
    return v >= lo && v < hi;
}

/* Every index the loaded world will follow, checked. */
static int consistent(const m2c_world *w, const header *h)
{
    if (w->n > w->cap || w->nverts > w->capverts || w->nparts > w->capparts || w->heap_n > w->n
        || w->nkin > w->n)
        return 0;
    for (int i = 0; i < w->n; i++) {
        const body *b = &w->b[i];
        if (b->nvert < 1 || b->vert < 0 || b->vert > w->nverts - b->nvert)
            return 0;
        if (b->nparts < 1 || b->part < 0 || b->part > w->nparts - b->nparts)
            return 0;
        int at = b->vert;
        for (int k = 0; k < b->nparts; k++) { /* the parts tile the body's vertices in order */
            const part *p = &w->parts[b->part + k];
            if (p->vert != at || p->nvert < 1 || !(p->radius >= 0))
                return 0;
            at += p->nvert;
        }
        if (at != b->vert + b->nvert)
            return 0;
        if (!in_range(b->kind, 0, KIND_REMOVED + 1) || !in_range(w->heap_pos[i], -1, w->heap_n))
            return 0;
        if (!in_range(b->next, -1, w->n) || !in_range(b->prev, -1, w->n)
            || !in_range(b->support, -1, w->n) || !in_range(b->ev.partner, -1, w->n))
            return 0;
        if (h->ncells && (!in_range(b->cx, 0, w->g.nx) || !in_range(b->cy, 0, w->g.ny)))
            return 0;
    }
    for (int k = 0; k < w->heap_n; k++)
        if (!in_range(w->heap[k], 0, w->n) || w->heap_pos[w->heap[k]] != k)
            return 0;
    for (int k = 0; k < w->nkin; k++)
        if (!in_range(w->kinematic[k], 0, w->n))
            return 0;
    for (int k = 0; k < w->nghosts; k++)
        if (!in_range(w->ghosts[k].a, 0, w->n) || !in_range(w->ghosts[k].b, 0, w->n))
            return 0;
    if (h->ncells) {
        if (w->g.nx < 1 || w->g.ny < 1 || (long long)w->g.nx * w->g.ny != h->ncells)
            return 0;
        for (int c = 0; c < h->ncells; c++)
            if (!in_range(w->g.head[c], -1, w->n) || w->g.fixed_start[c] < 0
                || w->g.fixed_start[c] > w->g.fixed_start[c + 1])
                return 0;
        if (w->g.fixed_start[0] != 0 || w->g.fixed_start[h->ncells] != h->nfixed)
            return 0;
        for (int k = 0; k < h->nfixed; k++)
            if (!in_range(w->g.fixed[k], 0, w->n))
                return 0;
    }
    return 1;
}

m2c_world *m2c_world_load(const void *buf, long long size)
{
    if (!buf || size < (long long)sizeof(header))
        return NULL;
    header h;
    memcpy(&h, buf, sizeof h);
    if (h.magic != MAGIC || h.version != VERSION || h.body_size != sizeof(body)
        || h.event_size != sizeof(m2c_event) || h.timer_size != sizeof(timer)
        || h.world_size != sizeof(m2c_world))
        return NULL;
    if (h.n < 0 || h.nverts < 0 || h.nparts < 0 || h.nkin < 0 || h.heap_n < 0 || h.ntimers < 0 || h.nghosts < 0
        || h.npending < 0 || h.ncells < 0 || h.nfixed < 0)
        return NULL;
    reader r = {buf, sizeof h, (size_t)size};
    m2c_world *w = take(&r, sizeof *w);
    if (!w)
        return NULL;
    /* the pointers are this process's own from here on: none of the saved ones survives */
    w->b = NULL;
    w->verts = w->edges = NULL;
    w->parts = NULL;
    w->heap = w->heap_pos = w->kinematic = w->stack = w->woken = w->members = NULL;
    w->timers = NULL;
    w->ghosts = NULL;
    w->pending = NULL;
    w->out = NULL;
    w->g.head = w->g.fixed_start = w->g.fixed = NULL;
    w->solver = NULL; /* (loaded below, after the bodies) */
    w->presolve = NULL;
    w->presolve_user = NULL;
    w->in_presolve = 0;
    int cap = h.n > 0 ? h.n : 1;
    w->n = h.n;
    w->cap = cap;
    w->nverts = w->capverts = h.nverts;
    w->nparts = w->capparts = h.nparts;
    w->nkin = h.nkin;
    w->heap_n = h.heap_n;
    w->ntimers = w->captimers = h.ntimers;
    w->nghosts = w->capghosts = h.nghosts;
    w->npending = w->cappending = h.npending;
    int ok = (w->b = take(&r, sizeof(body) * (size_t)h.n)) != NULL;
    if (ok) {
        body *grown = realloc(w->b, sizeof(body) * (size_t)cap);
        ok = grown != NULL;
        if (ok)
            w->b = grown;
    }
    ok = ok && (w->verts = take(&r, sizeof(double) * 2 * (size_t)h.nverts)) != NULL;
    ok = ok && (w->edges = take(&r, sizeof(double) * 3 * (size_t)h.nverts)) != NULL;
    ok = ok && (w->parts = take(&r, sizeof(part) * (size_t)h.nparts)) != NULL;
    int *kin = ok ? take(&r, sizeof(int) * (size_t)h.nkin) : NULL;
    int *heap = kin ? take(&r, sizeof(int) * (size_t)h.heap_n) : NULL;
    ok = ok && kin && heap;
    ok = ok && (w->heap_pos = take(&r, sizeof(int) * (size_t)h.n)) != NULL;
    ok = ok && (w->timers = take(&r, sizeof(timer) * (size_t)h.ntimers)) != NULL;
    ok = ok && (w->ghosts = take(&r, sizeof(pair) * (size_t)h.nghosts)) != NULL;
    ok = ok && (w->pending = take(&r, sizeof(m2c_event) * (size_t)h.npending)) != NULL;
    if (ok && h.ncells) {
        ok = (w->g.head = take(&r, sizeof(int) * (size_t)h.ncells)) != NULL;
        ok = ok && (w->g.fixed_start = take(&r, sizeof(int) * (size_t)(h.ncells + 1))) != NULL;
        ok = ok && (w->g.fixed = take(&r, sizeof(int) * (size_t)h.nfixed)) != NULL;
    }
    /* the per-body arrays at full capacity (the kinematic list, the heap, the scratch) */
    int *arrays[] = {NULL, NULL, NULL, NULL, NULL};
    for (int k = 0; ok && k < 5; k++)
        ok = (arrays[k] = calloc((size_t)cap, sizeof(int))) != NULL;
    if (ok) {
        memcpy(arrays[0], kin, sizeof(int) * (size_t)h.nkin);
        memcpy(arrays[1], heap, sizeof(int) * (size_t)h.heap_n);
        int *pos = realloc(w->heap_pos, sizeof(int) * (size_t)cap);
        ok = pos != NULL;
        if (ok)
            w->heap_pos = pos;
    }
    free(kin);
    free(heap);
    w->kinematic = arrays[0];
    w->heap = arrays[1];
    w->stack = arrays[2];
    w->woken = arrays[3];
    w->members = arrays[4];
    ok = ok && solver_load(w, get_into, &r) == 0;
    if (!ok || r.at != r.size || !consistent(w, &h) || !solver_consistent(w)) {
        m2c_world_free(w);
        return NULL;
    }
    return w;
}
