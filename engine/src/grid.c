/* grid.c -- the broad phase: a uniform cell list with cell-crossing events (De Michele,
 * arXiv:1009.1057). Cells are at least as wide as the two largest dynamic bodies together, so
 * two dynamic bodies can only touch while their reference points are in neighbouring cells;
 * a body is predicted against the 3x3 cells around its own, and only until it leaves its
 * cell (the crossing is its next event). Outside the grid's bounds the border cells extend
 * to infinity (crossings happen only at interior boundaries). Static bodies are listed in
 * every cell from which a dynamic body could reach them; kinematic bodies (few, and moving
 * anywhere) are checked by every body. */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "engine.h"

#define MAX_CELLS (1 << 22)

void grid_free(grid *g)
{
    free(g->head);
    free(g->fixed_start);
    free(g->fixed);
    g->head = g->fixed_start = g->fixed = NULL;
}

void grid_cell_of(const grid *g, double x, double y, int *cx, int *cy)
{
    double fx = floor((x - g->x0) / g->size), fy = floor((y - g->y0) / g->size);
    /* (NaN -- an infinite box's one cell -- is cell 0: never converted to int) */
    *cx = !(fx > 0) ? 0 : fx >= g->nx ? g->nx - 1 : (int)fx;
    *cy = !(fy > 0) ? 0 : fy >= g->ny ? g->ny - 1 : (int)fy;
}

static void link(m2c_world *w, int i)
{
    body *b = &w->b[i];
    int *head = &w->g.head[b->cy * w->g.nx + b->cx];
    b->prev = -1;
    b->next = *head;
    if (*head >= 0)
        w->b[*head].prev = i;
    *head = i;
}

static void unlink_body(m2c_world *w, int i)
{
    body *b = &w->b[i];
    if (b->prev >= 0)
        w->b[b->prev].next = b->next;
    else
        w->g.head[b->cy * w->g.nx + b->cx] = b->next;
    if (b->next >= 0)
        w->b[b->next].prev = b->prev;
    b->next = b->prev = -1;
}

void grid_remove(m2c_world *w, int i)
{
    unlink_body(w, i);
}

void grid_insert(m2c_world *w, int i)
{
    snap s = motion_at(&w->b[i].m, w->now);
    grid_cell_of(&w->g, s.x, s.y, &w->b[i].cx, &w->b[i].cy);
    link(w, i);
}

void grid_move(m2c_world *w, int i, int dx, int dy)
{
    unlink_body(w, i);
    body *b = &w->b[i];
    b->cx += dx;
    b->cy += dy;
    if (b->cx < 0) b->cx = 0;
    if (b->cx >= w->g.nx) b->cx = w->g.nx - 1;
    if (b->cy < 0) b->cy = 0;
    if (b->cy >= w->g.ny) b->cy = w->g.ny - 1;
    link(w, i);
}

/* Distance from (x, y) to one part's shape (its vertices and edges, radius included). */
static double part_distance(const m2c_world *w, const body *b, double x, double y)
{
    snap s = motion_at(&b->m, w->now);
    double best = INFINITY;
    int nedges = b->nvert >= 3 ? b->nvert : b->nvert - 1;
    for (int k = 0; k < b->nvert; k++) {
        double p[2];
        world_point(&s, &w->verts[2 * (b->vert + k)], p);
        double d = hypot(x - p[0], y - p[1]);
        if (d < best)
            best = d;
        if (k < nedges) {
            double u[2];
            const double *e = &w->edges[3 * (b->vert + k)];
            world_vector(&s, e, u);
            double along = (x - p[0]) * u[0] + (y - p[1]) * u[1];
            if (along > 0 && along < e[2]) {
                double across = fabs((x - p[0]) * u[1] - (y - p[1]) * u[0]);
                if (across < best)
                    best = across;
            }
        }
    }
    return best - b->radius;
}

/* Distance from (x, y) to body b's shape: its nearest part's. */
static double shape_distance(const m2c_world *w, const body *b, double x, double y)
{
    if (b->nparts == 1)
        return part_distance(w, b, x, y);
    double best = INFINITY;
    for (int k = 0; k < b->nparts; k++) {
        body v = part_view(w, b, k);
        best = fmin(best, part_distance(w, &v, x, y));
    }
    return best;
}

static void extend(double box[4], double x, double y, double r)
{
    if (x - r < box[0]) box[0] = x - r;
    if (y - r < box[1]) box[1] = y - r;
    if (x + r > box[2]) box[2] = x + r;
    if (y + r > box[3]) box[3] = y + r;
}

int grid_build(m2c_world *w)
{
    grid *g = &w->g;
    grid_free(g);
    double box[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    int ndyn = 0;
    w->bound_max = 0;
    for (int i = 0; i < w->n; i++) {
        const body *b = &w->b[i];
        if (b->kind == M2C_KINEMATIC || b->kind == KIND_REMOVED)
            continue;
        snap s = motion_at(&b->m, w->now);
        if (b->kind == M2C_STATIC) {
            for (int k = 0; k < b->nvert; k++) {
                double p[2];
                world_point(&s, &w->verts[2 * (b->vert + k)], p);
                extend(box, p[0], p[1], vertex_radius(w, b, k));
            }
        } else {
            extend(box, s.x, s.y, b->bound);
        }
        if (b->kind == M2C_DYNAMIC) {
            ndyn++;
            if (b->bound > w->bound_max)
                w->bound_max = b->bound;
        }
    }
    if (!(box[0] <= box[2])) { /* nothing but kinematic bodies */
        box[0] = box[1] = -1;
        box[2] = box[3] = 1;
    }
    double reach = w->bound_max + w->cfg.tolerance;
    double margin = 2 * reach + 1e-9 * (fabs(box[0]) + fabs(box[1]) + fabs(box[2]) + fabs(box[3]));
    box[0] -= margin;
    box[1] -= margin;
    box[2] += margin;
    box[3] += margin;
    double width = box[2] - box[0], height = box[3] - box[1];
    double size;
    double least = 2 * w->bound_max * (1 + 1e-9) + w->cfg.tolerance;
    if (w->cfg.cell_size < 0 || ndyn == 0) {
        size = fmax(width, height) * 2;
    } else if (w->cfg.cell_size > 0) {
        size = fmax(w->cfg.cell_size, least);
    } else {
        /* a little under one body per cell (measured: bench/engine_scaling.py; narrower cells
         * mean more crossings, wider ones more pairs per prediction), never narrower than the
         * bodies */
        size = fmax(least, 0.6 * sqrt(width * height / ndyn));
    }
    if (!(size > 0) || !isfinite(size))
        size = 1;
    double cells = ceil(width / size) * ceil(height / size);
    if (cells > MAX_CELLS)
        size *= sqrt(cells / MAX_CELLS) * 1.01;
    g->size = size;
    g->nx = (int)fmax(1, ceil(width / size));
    g->ny = (int)fmax(1, ceil(height / size));
    g->x0 = box[0];
    g->y0 = box[1];
    if (!(isfinite(width) && isfinite(height) && isfinite(size))) {
        /* bodies (or a tolerance) near the largest double: the box overflows; one cell holds
         * everything (no crossings, every static body listed) */
        g->size = INFINITY;
        g->nx = g->ny = 1;
        g->x0 = g->y0 = 0.0;
    }
    int ncells = g->nx * g->ny;
    g->head = malloc(sizeof(int) * (size_t)ncells);
    g->fixed_start = calloc((size_t)ncells + 1, sizeof(int));
    if (!g->head || !g->fixed_start)
        return -1;
    for (int c = 0; c < ncells; c++)
        g->head[c] = -1;
    /* static bodies: two passes (count, then fill) over the cells near each */
    double half_diagonal = size * 0.7072;
    for (int pass = 0; pass < 2; pass++) {
        int *fill = NULL;
        if (pass == 1) {
            for (int c = 0; c < ncells; c++)
                g->fixed_start[c + 1] += g->fixed_start[c];
            g->fixed = malloc(sizeof(int) * (size_t)(g->fixed_start[ncells] + 1));
            fill = calloc((size_t)ncells, sizeof(int));
            if (!g->fixed || !fill) {
                free(fill);
                return -1;
            }
        }
        for (int i = 0; i < w->n; i++) {
            const body *b = &w->b[i];
            if (b->kind != M2C_STATIC)
                continue;
            snap s = motion_at(&b->m, w->now);
            double bb[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
            for (int k = 0; k < b->nvert; k++) {
                double p[2];
                world_point(&s, &w->verts[2 * (b->vert + k)], p);
                extend(bb, p[0], p[1], vertex_radius(w, b, k) + reach + size);
            }
            int x0, y0, x1, y1;
            grid_cell_of(g, bb[0], bb[1], &x0, &y0);
            grid_cell_of(g, bb[2], bb[3], &x1, &y1);
            for (int cy = y0; cy <= y1; cy++)
                for (int cx = x0; cx <= x1; cx++) {
                    double mx = g->x0 + (cx + 0.5) * size, my = g->y0 + (cy + 0.5) * size;
                    if (ncells > 1 && shape_distance(w, b, mx, my) > reach + half_diagonal)
                        continue;
                    int c = cy * g->nx + cx;
                    if (pass == 0)
                        g->fixed_start[c + 1]++;
                    else
                        g->fixed[g->fixed_start[c] + fill[c]++] = i;
                }
        }
        free(fill);
    }
    for (int i = 0; i < w->n; i++)
        if (w->b[i].kind == M2C_DYNAMIC)
            grid_insert(w, i);
    w->st.ncells_x = g->nx;
    w->st.ncells_y = g->ny;
    w->st.cell_size = size;
    return 0;
}

double grid_crossing(const m2c_world *w, int i, double tmax, int *dx, int *dy)
{
    const grid *g = &w->g;
    const body *b = &w->b[i];
    snap s = motion_at(&b->m, w->now);
    double best = INFINITY, t;
    *dx = *dy = 0;
    if (b->cx > 0 && (t = first_crossing(s.x, s.vx, s.ax, g->x0 + b->cx * g->size, -1, tmax)) < best) {
        best = t; *dx = -1; *dy = 0;
    }
    if (b->cx < g->nx - 1 &&
        (t = first_crossing(s.x, s.vx, s.ax, g->x0 + (b->cx + 1) * g->size, 1, tmax)) < best) {
        best = t; *dx = 1; *dy = 0;
    }
    if (b->cy > 0 && (t = first_crossing(s.y, s.vy, s.ay, g->y0 + b->cy * g->size, -1, tmax)) < best) {
        best = t; *dx = 0; *dy = -1;
    }
    if (b->cy < g->ny - 1 &&
        (t = first_crossing(s.y, s.vy, s.ay, g->y0 + (b->cy + 1) * g->size, 1, tmax)) < best) {
        best = t; *dx = 0; *dy = 1;
    }
    return best;
}

void grid_neighbours(m2c_world *w, int i, visit_fn visit, void *ctx)
{
    const grid *g = &w->g;
    int cx = w->b[i].cx, cy = w->b[i].cy;
    for (int y = cy - 1; y <= cy + 1; y++) {
        if (y < 0 || y >= g->ny)
            continue;
        for (int x = cx - 1; x <= cx + 1; x++) {
            if (x < 0 || x >= g->nx)
                continue;
            for (int j = g->head[y * g->nx + x]; j >= 0; j = w->b[j].next)
                if (j != i)
                    visit(w, i, j, ctx);
        }
    }
    int c = cy * g->nx + cx;
    for (int k = g->fixed_start[c]; k < g->fixed_start[c + 1]; k++)
        if (w->b[g->fixed[k]].kind == M2C_STATIC) /* (removed or made dynamic since the build) */
            visit(w, i, g->fixed[k], ctx);
    for (int k = 0; k < w->nkin; k++)
        visit(w, i, w->kinematic[k], ctx);
}
