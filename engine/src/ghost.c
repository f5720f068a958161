/* ghost.c -- pairs that pass through each other: a contact vetoed by the pre-solve callback
 * (a one-way platform) or touching a sensor. Until the pair's next contact event (a new
 * crossing of one of its features' gaps), touching or overlapping is no contact for it
 * (predict.c: feat.ghost). A short list: few pairs pass through at once. */
#include <stdlib.h>

#include "engine.h"

int ghost_find(const m2c_world *w, int i, int j)
{
    int a = i < j ? i : j, b = i < j ? j : i;
    for (int k = 0; k < w->nghosts; k++)
        if (w->ghosts[k].a == a && w->ghosts[k].b == b)
            return k;
    return -1;
}

int ghost_add(m2c_world *w, int i, int j)
{
    if (ghost_find(w, i, j) >= 0)
        return 0;
    if (w->nghosts == w->capghosts) {
        int cap = w->capghosts ? 2 * w->capghosts : 16;
        pair *p = realloc(w->ghosts, sizeof(pair) * (size_t)cap);
        if (!p)
            return -1;
        w->ghosts = p;
        w->capghosts = cap;
    }
    w->ghosts[w->nghosts++] = (pair){i < j ? i : j, i < j ? j : i};
    return 0;
}

void ghost_remove_at(m2c_world *w, int k)
{
    w->ghosts[k] = w->ghosts[--w->nghosts];
}

void ghost_forget(m2c_world *w, int i)
{
    for (int k = w->nghosts - 1; k >= 0; k--)
        if (w->ghosts[k].a == i || w->ghosts[k].b == i)
            ghost_remove_at(w, k);
}

/* Body i was put somewhere else (set_pose, which refuses overlaps): it overlaps no sensor it
 * was passing through any more -- each such pair is left now. */
void ghost_leave_sensors(m2c_world *w, int i)
{
    for (int k = w->nghosts - 1; k >= 0; k--) {
        pair p = w->ghosts[k];
        if ((p.a != i && p.b != i) || !((w->b[p.a].flags | w->b[p.b].flags) & M2C_FLAG_SENSOR))
            continue;
        m2c_event e = {w->now, M2C_EVENT_SENSOR_LEAVE, i, p.a == i ? p.b : p.a, 0, 0, 0, 0, 0, 0};
        world_emit(w, &e);
        ghost_remove_at(w, k);
    }
}

/* Body i was just added: a sensor it overlaps (or, a sensor itself, a body it overlaps) is
 * entered now -- prediction finds only crossings, never a pair that starts inside. */
void ghost_enter_sensors(m2c_world *w, int i)
{
    const body *B = &w->b[i];
    for (int k = 0; k < w->n; k++) {
        const body *K = &w->b[k];
        if (k == i || K->kind == KIND_REMOVED || !((B->flags | K->flags) & M2C_FLAG_SENSOR)
            || !pair_filtered(B, K) || (B->kind != M2C_DYNAMIC && K->kind != M2C_DYNAMIC))
            continue;
        snap a = motion_at(&B->m, w->now), b = motion_at(&K->m, w->now);
        double dx = a.x - b.x, dy = a.y - b.y, reach = B->bound + K->bound;
        if (dx * dx + dy * dy > reach * reach || shape_signed_gap(w, i, k, w->now) >= -w->cfg.tolerance)
            continue;
        m2c_event e = {w->now, M2C_EVENT_SENSOR, i, k, 0, 0, 0, 0, 0, 0};
        if (world_emit(w, &e) == 0)
            ghost_add(w, i, k);
    }
}
