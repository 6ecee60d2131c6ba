/* "n closest triangles" and "all triangles within a distance d" (§4.4): the priority process of
 * §3.2 run past the first leaf, so leaves leave the queue in order of distance. */
#include <math.h>
#include <stdlib.h>

#include "core/core.h"
#include "sweep/sweep_heap.h"
#include "sweep/sweep_internal.h"

/* Regions farther than `radius` are never queued. Calls emit(element, d) for each leaf
 * popped, nearest first, until it returns nonzero. */
typedef int (*emit_fn)(void *user, uint32_t element, double d);

static void sweep_ordered(const fl_sweep *s, fl_sweep_heap *h, const double *q3, double radius,
                          emit_fn emit, void *user)
{
    double slack = fl_sweep_query_slack(s, q3), bary[3], c[3];
    h->n = 0;
    /* The root enters like any child: a one-element hierarchy's root is a leaf, and its key is
     * the distance that is emitted (an unconditional -inf key gave distance -inf and ignored
     * the radius). */
    const fl_sweep_node *root = s->nodes;
    double lo0 = fl_sweep_is_leaf(root) ? fl_sweep_node_distance(s, root, q3, bary, c) : -INFINITY;
    if (lo0 <= radius) fl_sweep_heap_push(h, (fl_sweep_entry){lo0, 0, 0, 0});
    while (h->n > 0) {
        fl_sweep_entry top = fl_sweep_heap_pop(h);
        const fl_sweep_node *node = s->nodes + top.node;
        if (fl_sweep_is_leaf(node)) {
            if (emit(user, node->element, top.key)) return;
            continue;
        }
        for (int k = 0; k < 2; k++) {
            const fl_sweep_node *child = s->nodes + node->child[k];
            double d = fl_sweep_node_distance(s, child, q3, bary, c);
            double lo = fl_sweep_is_leaf(child) ? d : d - child->eps - slack;
            if (lo <= radius) fl_sweep_heap_push(h, (fl_sweep_entry){lo, 0, node->child[k], 0});
        }
    }
}

typedef struct knearest_out {
    uint32_t *elements;
    double *distances;
    size_t k, found;
} knearest_out;

static int emit_knearest(void *user, uint32_t element, double d)
{
    knearest_out *o = user;
    o->elements[o->found] = element;
    o->distances[o->found] = d;
    return ++o->found == o->k;
}

static fl_status ordered_setup(const fl_sweep *sweep, const double *q, double *q3, fl_sweep_heap *h,
                               fl_error *err)
{
    if (!sweep || !q)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "sweep and query must not be NULL");
    if (!fl_sweep_lift_query(sweep, q, q3))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "query point is not finite or beyond 1e150");
    h->n = 0;
    h->e = fl_alloc_array(sweep->node_count, sizeof *h->e);
    if (!h->e) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for a sweep query");
    return FL_OK;
}

fl_status fl_sweep_knearest(const fl_sweep *sweep, const double *q, size_t k, uint32_t *elements,
                            double *distances, size_t *found, fl_error *err)
{
    if (!found || (k > 0 && (!elements || !distances)))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "output arrays must not be NULL");
    *found = 0;
    double q3[3];
    fl_sweep_heap h = {NULL, 0};
    fl_status st = ordered_setup(sweep, q, q3, &h, err);
    if (st != FL_OK || k == 0) {
        free(h.e);
        return st;
    }
    knearest_out o = {elements, distances, k, 0};
    sweep_ordered(sweep, &h, q3, INFINITY, emit_knearest, &o);
    free(h.e);
    *found = o.found;
    return FL_OK;
}

typedef struct hit {
    uint32_t element;
    double d;
} hit;

typedef struct within_out {
    fl_vec hits;
    int failed; /* an allocation failed and stopped the search */
} within_out;

static int emit_within(void *user, uint32_t element, double d)
{
    within_out *o = user;
    hit one = {element, d};
    o->failed = fl_vec_push(&o->hits, &one, 1) != 0;
    return o->failed;
}

fl_status fl_sweep_within(const fl_sweep *sweep, const double *q, double radius, fl_sweep_hits *out,
                          fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "output must not be NULL");
    *out = (fl_sweep_hits){0, NULL, NULL};
    if (!(radius >= 0)) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "radius must be >= 0");
    double q3[3];
    fl_sweep_heap h = {NULL, 0};
    fl_status st = ordered_setup(sweep, q, q3, &h, err);
    if (st != FL_OK) return st;
    within_out o = {.failed = 0};
    fl_vec_init(&o.hits, sizeof(hit));
    sweep_ordered(sweep, &h, q3, radius, emit_within, &o);
    free(h.e);
    size_t n = o.hits.count;
    if (!o.failed) {
        out->element = fl_alloc_array(n ? n : 1, sizeof *out->element);
        out->distance = fl_alloc_array(n ? n : 1, sizeof *out->distance);
        o.failed = !out->element || !out->distance;
    }
    if (o.failed) {
        fl_vec_free(&o.hits);
        fl_sweep_hits_free(out);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the hits of a query");
    }
    const hit *all = o.hits.data;
    for (size_t i = 0; i < n; i++) {
        out->element[i] = all[i].element;
        out->distance[i] = all[i].d;
    }
    out->count = n;
    fl_vec_free(&o.hits);
    return FL_OK;
}

void fl_sweep_hits_free(fl_sweep_hits *hits)
{
    if (!hits) return;
    free(hits->element);
    free(hits->distance);
    *hits = (fl_sweep_hits){0, NULL, NULL};
}
