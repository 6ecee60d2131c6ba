/* Graph containers and the input checks shared by every graph builder. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "graphs/gamma_internal.h"

void fl_graph_free(fl_graph *graph)
{
    if (!graph) return;
    free(graph->simplices);
    free(graph->params);
    memset(graph, 0, sizeof *graph);
}

void graph_builder_init(graph_builder *b, int dim, int simplex_size, size_t n)
{
    b->dim = dim;
    b->simplex_size = simplex_size;
    b->vertex_count = n;
    fl_vec_init(&b->records, sizeof(graph_record));
}

void graph_builder_free(graph_builder *b)
{
    fl_vec_free(&b->records);
}

int graph_builder_add(graph_builder *b, const uint32_t *s, double c0, double c1)
{
    graph_record r = {{0, 0, 0}, c0, c1};
    memcpy(r.v, s, (size_t)b->simplex_size * sizeof(uint32_t));
    for (int i = 1; i < b->simplex_size; i++) /* insertion sort of 2 or 3 indices */
        for (int j = i; j > 0 && r.v[j - 1] > r.v[j]; j--) {
            uint32_t t = r.v[j];
            r.v[j] = r.v[j - 1];
            r.v[j - 1] = t;
        }
    return fl_vec_push(&b->records, &r, 1);
}

static int record_cmp(const void *pa, const void *pb)
{
    const graph_record *a = pa, *b = pb;
    for (int i = 0; i < 3; i++)
        if (a->v[i] != b->v[i]) return a->v[i] < b->v[i] ? -1 : 1;
    return 0;
}

fl_status graph_builder_finish(graph_builder *b, int want_params, fl_graph *out, fl_error *err)
{
    graph_record *r = b->records.data;
    size_t count = 0, k = (size_t)b->simplex_size;
    if (b->records.count) qsort(r, b->records.count, sizeof *r, record_cmp);
    for (size_t i = 0; i < b->records.count; i++)
        if (count == 0 || record_cmp(&r[count - 1], &r[i]) != 0) r[count++] = r[i];
    memset(out, 0, sizeof *out);
    out->simplices = fl_alloc_array(count, k * sizeof(uint32_t));
    out->params = want_params ? fl_alloc_array(count, 2 * sizeof(double)) : NULL;
    if (!out->simplices || (want_params && !out->params)) {
        fl_graph_free(out);
        graph_builder_free(b);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory storing %zu simplices", count);
    }
    for (size_t i = 0; i < count; i++) {
        memcpy(out->simplices + i * k, r[i].v, k * sizeof(uint32_t));
        if (want_params) {
            out->params[2 * i] = r[i].c0;
            out->params[2 * i + 1] = r[i].c1;
        }
    }
    out->dim = b->dim;
    out->vertex_count = b->vertex_count;
    out->simplex_size = b->simplex_size;
    out->simplex_count = count;
    graph_builder_free(b);
    return FL_OK;
}

typedef struct point_key {
    const double *p;
    int dim;
    uint32_t index;
} point_key;

static int point_key_cmp(const void *pa, const void *pb)
{
    const point_key *a = pa, *b = pb;
    for (int i = 0; i < a->dim; i++)
        if (a->p[i] != b->p[i]) return a->p[i] < b->p[i] ? -1 : 1;
    return a->index < b->index ? -1 : a->index > b->index;
}

/* Equal coordinates (so -0.0 and 0.0 are the same point). */
static int same_point(const double *a, const double *b, int dim)
{
    for (int i = 0; i < dim; i++)
        if (a[i] != b[i]) return 0;
    return 1;
}

fl_status graph_check_points(const double *coords, size_t n, int dim, fl_error *err)
{
    if (dim != 2 && dim != 3)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "graphs need 2D or 3D points, got dim=%d", dim);
    if (n >= UINT32_MAX)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "%zu points exceed 32-bit indices", n);
    if (n && !coords) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "coords is NULL");
    for (size_t i = 0; i < n * (size_t)dim; i++)
        if (!isfinite(coords[i]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "point %zu has a non-finite coordinate; remove or fix it", i / dim);
    point_key *keys = fl_alloc_array(n, sizeof *keys);
    if (!keys) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory checking %zu points", n);
    for (size_t i = 0; i < n; i++)
        keys[i] = (point_key){coords + i * (size_t)dim, dim, (uint32_t)i};
    if (n) qsort(keys, n, sizeof *keys, point_key_cmp);
    fl_status st = FL_OK;
    for (size_t i = 1; i < n && st == FL_OK; i++)
        if (same_point(keys[i - 1].p, keys[i].p, dim))
            st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                         "points %u and %u coincide; the γ-graph needs distinct points "
                         "(remove duplicates first)",
                         (unsigned)keys[i - 1].index, (unsigned)keys[i].index);
    free(keys);
    return st;
}

static int in_unit(double c)
{
    return c >= -1.0 && c <= 1.0;
} /* false for NaN */

fl_status gamma_check_params(const fl_gamma_params *p, fl_error *err)
{
    if (!p) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "γ parameters missing");
    int nc = p->range ? 4 : 2;
    for (int i = 0; i < nc; i++)
        if (!in_unit(p->c[i]))
            return fl_fail(err, FL_ERR_USAGE, NULL, -1, "γ parameter c%d = %g is not in [-1,1]", i,
                           p->c[i]);
    if (!p->range && fabs(p->c[0]) > fabs(p->c[1]))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "γ(c0,c1) needs |c0| <= |c1| (Def. 3.1), got c0=%g, c1=%g", p->c[0],
                       p->c[1]);
    if (p->range && (p->c[0] > p->c[1] || p->c[2] > p->c[3]))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "γ([c0,c1],[c2,c3]) needs c0 <= c1 and c2 <= c3, got [%g,%g],[%g,%g]",
                       p->c[0], p->c[1], p->c[2], p->c[3]);
    return FL_OK;
}
