/* A uniform bucket grid over the bounding box: the neighbourhood searches of the graph builders
 * (lens candidates, witness gathering, skeleton emptiness) touch only nearby cells. Cells are a
 * filter only: every decision is made afterwards by exact predicates on the points returned. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "graphs/gamma_internal.h"

static size_t cell_coord(const graph_grid *g, int axis, double x)
{
    double c = floor((x - g->lo[axis]) / g->cell);
    if (!(c >= 0)) return 0;
    if (c >= (double)g->res[axis]) return g->res[axis] - 1;
    return (size_t)c;
}

static size_t cell_index(const graph_grid *g, const size_t *c)
{
    size_t idx = 0;
    for (int a = g->dim - 1; a >= 0; a--)
        idx = idx * g->res[a] + c[a];
    return idx;
}

static void grid_shape(graph_grid *g)
{
    double hi[3] = {0, 0, 0}, volume = 1;
    for (int a = 0; a < g->dim; a++) {
        g->lo[a] = hi[a] = g->n ? g->coords[a] : 0;
        for (size_t i = 1; i < g->n; i++) {
            double x = g->coords[i * (size_t)g->dim + a];
            g->lo[a] = fmin(g->lo[a], x);
            hi[a] = fmax(hi[a], x);
        }
    }
    double ext_max = 0;
    for (int a = 0; a < g->dim; a++)
        ext_max = fmax(ext_max, hi[a] - g->lo[a]);
    if (ext_max == 0) ext_max = 1;
    for (int a = 0; a < g->dim; a++)
        volume *= fmax(hi[a] - g->lo[a], ext_max * 1e-3);
    /* About two points a cell, and never more cells than 4n (flat or thin sets). */
    g->cell = pow(volume * 2.0 / (double)(g->n ? g->n : 1), 1.0 / g->dim);
    for (;;) {
        double cells = 1;
        for (int a = 0; a < g->dim; a++) {
            double r = floor((hi[a] - g->lo[a]) / g->cell) + 1;
            /* Extents beyond DBL_MAX (coordinates near ±1e308) make r NaN (inf / inf): one
             * cell along the axis, the grid being a filter only (found by fuzz/fuzz_graphs.c;
             * tests/degenerate/test_graphs_degenerate.c). */
            if (!(r >= 1 && r <= 0x1p52)) r = 1;
            g->res[a] = (size_t)r;
            cells *= r;
        }
        if (cells <= 4.0 * (double)g->n + 64) break;
        g->cell *= 1.5;
    }
}

fl_status graph_grid_build(graph_grid *g, const double *coords, size_t n, int dim, fl_error *err)
{
    memset(g, 0, sizeof *g);
    g->dim = dim;
    g->coords = coords;
    g->n = n;
    grid_shape(g);
    size_t cells = 1;
    for (int a = 0; a < dim; a++)
        cells *= g->res[a];
    g->start = fl_calloc_array(cells + 1, sizeof *g->start);
    g->items = fl_alloc_array(n, sizeof *g->items);
    size_t *cell_of = fl_alloc_array(n, sizeof *cell_of);
    if (!g->start || !g->items || !cell_of) {
        free(cell_of);
        graph_grid_free(g);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for a grid of %zu cells", cells);
    }
    for (size_t i = 0; i < n; i++) {
        size_t c[3] = {0, 0, 0};
        for (int a = 0; a < dim; a++)
            c[a] = cell_coord(g, a, coords[i * (size_t)dim + a]);
        cell_of[i] = cell_index(g, c);
        g->start[cell_of[i] + 1]++;
    }
    for (size_t c = 0; c < cells; c++)
        g->start[c + 1] += g->start[c];
    for (size_t i = 0; i < n; i++)
        g->items[g->start[cell_of[i]]++] = (uint32_t)i;
    for (size_t c = cells; c > 0; c--)
        g->start[c] = g->start[c - 1];
    g->start[0] = 0;
    free(cell_of);
    return FL_OK;
}

void graph_grid_free(graph_grid *g)
{
    free(g->start);
    free(g->items);
    g->start = NULL;
    g->items = NULL;
}

static int push_cell(const graph_grid *g, const size_t *c, fl_vec *out)
{
    size_t idx = cell_index(g, c);
    size_t count = g->start[idx + 1] - g->start[idx];
    return count ? fl_vec_push(out, g->items + g->start[idx], count) : 0;
}

int graph_grid_box(const graph_grid *g, const double *lo, const double *hi, fl_vec *out)
{
    size_t a0[3] = {0, 0, 0}, a1[3] = {0, 0, 0}, c[3];
    for (int a = 0; a < g->dim; a++) {
        a0[a] = cell_coord(g, a, lo[a]);
        a1[a] = cell_coord(g, a, hi[a]);
    }
    for (c[2] = a0[2]; c[2] <= a1[2]; c[2]++)
        for (c[1] = a0[1]; c[1] <= a1[1]; c[1]++)
            for (c[0] = a0[0]; c[0] <= a1[0]; c[0]++)
                if (push_cell(g, c, out)) return -1;
    return 0;
}

int graph_grid_slab(const graph_grid *g, const double *lo, const double *hi, const double *center,
                    const double *normal, double half, fl_vec *out)
{
    size_t a0[3] = {0, 0, 0}, a1[3] = {0, 0, 0}, c[3];
    double ext[3] = {0, 0, 0}, reach = 0; /* a cell's half-extent; its reach along the normal */
    for (int a = 0; a < g->dim; a++) {
        a0[a] = cell_coord(g, a, lo[a]);
        a1[a] = cell_coord(g, a, hi[a]);
        /* one cell along an axis may hold points beyond its nominal width (see grid_shape) */
        ext[a] = g->res[a] > 1 ? g->cell / 2 : INFINITY;
        reach += ext[a] * fabs(normal[a]);
    }
    if (!(reach < INFINITY)) return graph_grid_box(g, lo, hi, out);
    for (c[2] = a0[2]; c[2] <= a1[2]; c[2]++)
        for (c[1] = a0[1]; c[1] <= a1[1]; c[1]++)
            for (c[0] = a0[0]; c[0] <= a1[0]; c[0]++) {
                double h = 0;
                for (int a = 0; a < g->dim; a++)
                    h += (g->lo[a] + ((double)c[a] + 0.5) * g->cell - center[a]) * normal[a];
                if (!(fabs(h) <= half + reach * (1 + 1e-9))) continue;
                if (push_cell(g, c, out)) return -1;
            }
    return 0;
}

long graph_grid_ring(const graph_grid *g, const double *p, size_t ring, fl_vec *out, int *beyond)
{
    size_t before = out->count, home[3] = {0, 0, 0};
    long lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    int inside = 0;
    for (int a = 0; a < g->dim; a++) {
        home[a] = cell_coord(g, a, p[a]);
        lo[a] = (long)home[a] - (long)ring;
        hi[a] = (long)home[a] + (long)ring;
        if (lo[a] >= 0 || hi[a] < (long)g->res[a]) inside = 1;
    }
    *beyond = !inside;
    /* Walk only the shell: rows on a face of the cube are whole, other rows are two cells. */
    long c[3] = {0, 0, 0};
    long z0 = g->dim == 3 ? lo[2] : 0, z1 = g->dim == 3 ? hi[2] : 0;
    for (c[2] = z0; c[2] <= z1; c[2]++) {
        if (c[2] < 0 || c[2] >= (long)(g->dim == 3 ? g->res[2] : 1)) continue;
        for (c[1] = lo[1]; c[1] <= hi[1]; c[1]++) {
            if (c[1] < 0 || c[1] >= (long)g->res[1]) continue;
            int face =
                c[1] == lo[1] || c[1] == hi[1] || (g->dim == 3 && (c[2] == z0 || c[2] == z1));
            long step = face || hi[0] == lo[0] ? 1 : hi[0] - lo[0];
            for (c[0] = lo[0]; c[0] <= hi[0]; c[0] += step) {
                if (c[0] < 0 || c[0] >= (long)g->res[0]) continue;
                size_t cc[3] = {(size_t)c[0], (size_t)c[1], (size_t)c[2]};
                if (push_cell(g, cc, out)) return -1;
            }
        }
    }
    return (long)(out->count - before);
}
