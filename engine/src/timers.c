/* timers.c -- pending timers: a binary min-heap keyed by (time, id), so that timers due at one
 * time fire in the order they were set (ids increase). Adding and firing are O(log n): the
 * sorted array they replace shifted every entry on each firing, and 10^6 timers took minutes
 * (issue 33). */
#include <stdlib.h>

#include "engine.h"

static int earlier(const timer *a, const timer *b)
{
    return a->t < b->t || (a->t == b->t && a->id < b->id);
}

static void sift_up(timer *h, int k)
{
    timer x = h[k];
    while (k > 0 && earlier(&x, &h[(k - 1) / 2])) {
        h[k] = h[(k - 1) / 2];
        k = (k - 1) / 2;
    }
    h[k] = x;
}

static void sift_down(timer *h, int n, int k)
{
    timer x = h[k];
    for (;;) {
        int c = 2 * k + 1;
        if (c >= n)
            break;
        if (c + 1 < n && earlier(&h[c + 1], &h[c]))
            c++;
        if (!earlier(&h[c], &x))
            break;
        h[k] = h[c];
        k = c;
    }
    h[k] = x;
}

int timer_push(m2c_world *w, double t, int id)
{
    if (w->ntimers == w->captimers) {
        int cap = w->captimers ? 2 * w->captimers : 8;
        timer *n = realloc(w->timers, sizeof(timer) * (size_t)cap);
        if (!n)
            return -1;
        w->timers = n;
        w->captimers = cap;
    }
    w->timers[w->ntimers] = (timer){t, id};
    sift_up(w->timers, w->ntimers++);
    return 0;
}

/* Remove the entry at heap position k. */
static void remove_at(m2c_world *w, int k)
{
    timer *h = w->timers;
    int last = --w->ntimers;
    if (k == last)
        return;
    h[k] = h[last];
    if (k > 0 && earlier(&h[k], &h[(k - 1) / 2]))
        sift_up(h, k);
    else
        sift_down(h, w->ntimers, k);
}

void timer_pop(m2c_world *w)
{
    if (w->ntimers > 0)
        remove_at(w, 0);
}

int timer_remove(m2c_world *w, int id)
{
    for (int k = 0; k < w->ntimers; k++) /* (a search: cancelling is rare) */
        if (w->timers[k].id == id) {
            remove_at(w, k);
            return 0;
        }
    return -1;
}
