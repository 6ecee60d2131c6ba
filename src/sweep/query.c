/* The priority process of §3.2 on intervals [d - ε, d + ε] keyed by d - ε, shared by polylines
 * and meshes (§4.2: "nothing else is changed in the priority structure"), with the pruning by
 * the best upper bound, the early stop on a tolerance, the constant-time coherence ball of
 * §3.3, and the n-closest / within-distance variants of §4.4.
 *
 * Rounding: every lower bound is lowered and every upper bound raised by a slack of a few ulps
 * of the largest coordinate involved, so pruning never discards a region that could hold a
 * nearer point than the one returned, beyond that slack. A leaf's key is its distance itself,
 * so the first leaf to leave the queue is the closest element. */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "core/core.h"
#include "sweep/sweep_internal.h"

typedef struct heap_entry {
    double key;
    uint32_t node;
} heap_entry;

/* A binary min-heap on an array sized once for all the nodes (each node enters at most once
 * per query), so a query allocates nothing. */
typedef struct heap {
    heap_entry *e;
    size_t n;
} heap;

static void heap_push(heap *h, double key, uint32_t node)
{
    size_t i = h->n++;
    while (i > 0 && h->e[(i - 1) / 2].key > key) {
        h->e[i] = h->e[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    h->e[i] = (heap_entry){key, node};
}

static heap_entry heap_pop(heap *h)
{
    heap_entry top = h->e[0], last = h->e[--h->n];
    size_t i = 0;
    for (;;) {
        size_t c = 2 * i + 1;
        if (c >= h->n) break;
        if (c + 1 < h->n && h->e[c + 1].key < h->e[c].key) c++;
        if (h->e[c].key >= last.key) break;
        h->e[i] = h->e[c];
        i = c;
    }
    if (h->n > 0) h->e[i] = last;
    return top;
}

struct fl_sweep_cursor {
    const fl_sweep *s;
    heap h;
    int have_ball; /* §3.3: the last exact answer's ball is valid */
    double center[3];
    double radius;
    uint32_t leaf; /* the node that is closest anywhere inside the ball */
};

static int is_leaf(const fl_sweep_node *node)
{
    return node->child[0] == FL_SWEEP_LEAF;
}

static double query_slack(const fl_sweep *s, const double *q)
{
    double m = fmax(fmax(fabs(q[0]), fabs(q[1])), fabs(q[2]));
    return 64 * DBL_EPSILON * (s->scale + m);
}

/* Lifts a query of dimension s->dim to 3D; 0 if it is not finite. */
static int lift_query(const fl_sweep *s, const double *q, double *q3)
{
    for (int c = 0; c < 3; c++) {
        q3[c] = c < s->dim ? q[c] : 0;
        if (!isfinite(q3[c])) return 0;
    }
    return 1;
}

static void fill_leaf(const fl_sweep *s, uint32_t leaf, const double *q3, fl_closest *r)
{
    const fl_sweep_node *node = s->nodes + leaf;
    r->distance = fl_sweep_node_distance(s, node, q3, r->bary, r->point);
    r->element = node->element;
    r->lower = r->upper = r->distance;
    r->exact = 1;
}

/* The search state of one closest-point query. */
typedef struct search {
    double upper;      /* best upper bound so far (§3.2) */
    double min_pruned; /* smallest lower bound of a region pruned on arrival (§3.3) */
    uint32_t best_leaf;
    double best_leaf_d;
    double slack;
    size_t visited;
} search;

/* An upper bound on the distance from q to the shape inside a region. §3.1's d + ε needs the
 * base element to lie within ε of the shape as well, which the end-point fit guarantees (the
 * curve crosses every plane normal to the segment inside the capsule's ε-disc). Our mesh
 * elements only bound the shape one way (their triangles overhang it), so a mesh region
 * uses the distance to a vertex of the shape inside it instead. */
static double upper_bound(const fl_sweep *s, const fl_sweep_node *node, const double *q3, double d,
                          double slack)
{
    if (!s->triangles) return d + node->eps + slack;
    double r2 = 0;
    for (int c = 0; c < 3; c++)
        r2 += (q3[c] - node->rep[c]) * (q3[c] - node->rep[c]);
    return sqrt(r2) + slack;
}

/* Computes a region's interval and queues it unless the best upper bound prunes it. */
static void visit(const fl_sweep *s, heap *h, search *st, const double *q3, uint32_t id)
{
    const fl_sweep_node *node = s->nodes + id;
    double bary[3], c[3];
    double d = fl_sweep_node_distance(s, node, q3, bary, c);
    st->visited++;
    double lo = d, hi = d;
    if (!is_leaf(node)) {
        lo = d - node->eps - st->slack;
        hi = upper_bound(s, node, q3, d, st->slack);
    } else if (d < st->best_leaf_d) {
        st->best_leaf_d = d;
        st->best_leaf = id;
    }
    if (hi < st->upper) st->upper = hi;
    if (lo > st->upper) {
        if (lo < st->min_pruned) st->min_pruned = lo;
        return;
    }
    heap_push(h, lo, id);
}

/* §3.3: no other region can come nearer than the second interval's lower end, so within half
 * the gap the answer keeps its element. */
static void set_ball(fl_sweep_cursor *cur, const search *st, const double *q3, uint32_t leaf,
                     double d)
{
    double second = st->min_pruned;
    if (cur->h.n > 0 && cur->h.e[0].key < second) second = cur->h.e[0].key;
    double r = (second - d) / 2 - st->slack;
    cur->have_ball = r > 0;
    cur->radius = r;
    cur->leaf = leaf;
    for (int c = 0; c < 3; c++)
        cur->center[c] = q3[c];
}

static void approximate(const fl_sweep *s, const search *st, double lower, const double *q3,
                        fl_closest *r)
{
    if (st->best_leaf != FL_SWEEP_LEAF) {
        fill_leaf(s, st->best_leaf, q3, r);
    } else {
        r->element = FL_SWEEP_NONE;
        for (int c = 0; c < 3; c++)
            r->point[c] = r->bary[c] = NAN;
    }
    r->lower = lower > 0 ? lower : 0;
    r->upper = st->upper;
    r->distance = (r->lower + r->upper) / 2;
    r->exact = 0;
}

/* The priority process (§3.2): pop the lowest lower bound, split it, prune by the best upper
 * bound; the first leaf popped is the answer, or stop once the interval fits the tolerance. */
static void sweep_query(fl_sweep_cursor *cur, const double *q3, double tol, fl_closest *r)
{
    const fl_sweep *s = cur->s;
    search st = {INFINITY, INFINITY, FL_SWEEP_LEAF, INFINITY, query_slack(s, q3), 0};
    heap *h = &cur->h;
    h->n = 0;
    cur->have_ball = 0;
    visit(s, h, &st, q3, 0);
    while (h->n > 0) {
        const fl_sweep_node *node = s->nodes + h->e[0].node;
        if (!is_leaf(node) && tol > 0 && st.upper - h->e[0].key <= tol) {
            approximate(s, &st, h->e[0].key, q3, r);
            break;
        }
        heap_entry top = heap_pop(h);
        if (is_leaf(node)) {
            fill_leaf(s, top.node, q3, r);
            set_ball(cur, &st, q3, top.node, r->distance);
            break;
        }
        visit(s, h, &st, q3, node->child[0]);
        visit(s, h, &st, q3, node->child[1]);
    }
    r->reused = 0;
    r->visited = st.visited;
}

fl_status fl_sweep_cursor_new(const fl_sweep *sweep, fl_sweep_cursor **out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "output pointer is NULL");
    *out = NULL;
    if (!sweep) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "sweep hierarchy is NULL");
    fl_sweep_cursor *cur = calloc(1, sizeof *cur);
    heap_entry *e = fl_alloc_array(sweep->node_count, sizeof *e);
    if (!cur || !e) {
        free(cur);
        free(e);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for a sweep cursor");
    }
    cur->s = sweep;
    cur->h.e = e;
    *out = cur;
    return FL_OK;
}

void fl_sweep_cursor_free(fl_sweep_cursor *cursor)
{
    if (!cursor) return;
    free(cursor->h.e);
    free(cursor);
}

fl_status fl_sweep_cursor_closest(fl_sweep_cursor *cursor, const double *q, double tolerance,
                                  fl_closest *result, fl_error *err)
{
    double q3[3];
    if (!cursor || !q || !result)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "cursor, query and result must not be NULL");
    if (!(tolerance >= 0)) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "tolerance must be >= 0");
    if (!lift_query(cursor->s, q, q3))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "query point is not finite");
    if (cursor->have_ball) {
        double d2 = 0;
        for (int c = 0; c < 3; c++)
            d2 += (q3[c] - cursor->center[c]) * (q3[c] - cursor->center[c]);
        if (sqrt(d2) < cursor->radius) {
            fill_leaf(cursor->s, cursor->leaf, q3, result);
            result->reused = 1;
            result->visited = 1;
            return FL_OK;
        }
    }
    sweep_query(cursor, q3, tolerance, result);
    return FL_OK;
}

fl_status fl_sweep_closest(const fl_sweep *sweep, const double *q, size_t nq, double tolerance,
                           fl_closest *results, fl_error *err)
{
    if (nq == 0) return FL_OK;
    if (!q || !results)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "queries and results must not be NULL");
    fl_sweep_cursor *cur;
    fl_status st = fl_sweep_cursor_new(sweep, &cur, err);
    if (st != FL_OK) return st;
    for (size_t i = 0; i < nq && st == FL_OK; i++)
        st = fl_sweep_cursor_closest(cur, q + i * (size_t)sweep->dim, tolerance, results + i, err);
    fl_sweep_cursor_free(cur);
    return st;
}

/* §4.4: keep running the priority process past the first leaf; leaves leave the queue in
 * order of distance. Regions farther than `radius` are never queued. Calls emit(leaf, d) for
 * each leaf popped until it returns nonzero. */
typedef int (*emit_fn)(void *user, uint32_t element, double d);

static void sweep_ordered(const fl_sweep *s, heap *h, const double *q3, double radius, emit_fn emit,
                          void *user)
{
    double slack = query_slack(s, q3), bary[3], c[3];
    h->n = 0;
    heap_push(h, -INFINITY, 0);
    while (h->n > 0) {
        heap_entry top = heap_pop(h);
        const fl_sweep_node *node = s->nodes + top.node;
        if (is_leaf(node)) {
            if (emit(user, node->element, top.key)) return;
            continue;
        }
        for (int k = 0; k < 2; k++) {
            const fl_sweep_node *child = s->nodes + node->child[k];
            double d = fl_sweep_node_distance(s, child, q3, bary, c);
            double lo = is_leaf(child) ? d : d - child->eps - slack;
            if (lo <= radius) heap_push(h, lo, node->child[k]);
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

static fl_status ordered_setup(const fl_sweep *sweep, const double *q, double *q3, heap *h,
                               fl_error *err)
{
    if (!sweep || !q)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "sweep and query must not be NULL");
    if (!lift_query(sweep, q, q3))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "query point is not finite");
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
    heap h;
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
    heap h;
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
