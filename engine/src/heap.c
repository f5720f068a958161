/* heap.c -- the event queue: an indexed binary heap of dynamic bodies keyed by
 * (event time, body id). One slot per body, so there is never a stale entry to skip and the
 * heap never grows; ties between equal times go to the lower id (a deterministic order). */
#include <stdlib.h>

#include "engine.h"

static int before(const m2c_world *w, int i, int j)
{
    double ti = w->b[i].ev.t, tj = w->b[j].ev.t;
    return ti < tj || (ti == tj && i < j);
}

static void place(m2c_world *w, int k, int i)
{
    w->heap[k] = i;
    w->heap_pos[i] = k;
}

static void sift_up(m2c_world *w, int k)
{
    int i = w->heap[k];
    while (k > 0) {
        int parent = (k - 1) / 2;
        if (!before(w, i, w->heap[parent]))
            break;
        place(w, k, w->heap[parent]);
        k = parent;
    }
    place(w, k, i);
}

static void sift_down(m2c_world *w, int k)
{
    int i = w->heap[k];
    for (;;) {
        int child = 2 * k + 1;
        if (child >= w->heap_n)
            break;
        if (child + 1 < w->heap_n && before(w, w->heap[child + 1], w->heap[child]))
            child++;
        if (!before(w, w->heap[child], i))
            break;
        place(w, k, w->heap[child]);
        k = child;
    }
    place(w, k, i);
}

int heap_init(m2c_world *w, int capacity)
{
    int *h = realloc(w->heap, sizeof(int) * (size_t)capacity);
    if (!h)
        return -1;
    w->heap = h;
    int *p = realloc(w->heap_pos, sizeof(int) * (size_t)capacity);
    if (!p)
        return -1;
    w->heap_pos = p;
    return 0;
}

void heap_insert(m2c_world *w, int i)
{
    int k = w->heap_n++;
    place(w, k, i);
    sift_up(w, k);
}

void heap_update(m2c_world *w, int i)
{
    int k = w->heap_pos[i];
    if (k < 0)
        return;
    if (k > 0 && before(w, i, w->heap[(k - 1) / 2]))
        sift_up(w, k);
    else
        sift_down(w, k);
}

int heap_top(const m2c_world *w)
{
    return w->heap_n > 0 ? w->heap[0] : -1;
}

/* Take body i out of the queue (removed, or no longer dynamic). */
void heap_remove(m2c_world *w, int i)
{
    int k = w->heap_pos[i];
    if (k < 0)
        return;
    w->heap_pos[i] = -1;
    int last = w->heap[--w->heap_n];
    if (last == i)
        return;
    place(w, k, last);
    heap_update(w, last);
}
