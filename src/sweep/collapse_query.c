/* Queries on the edge-collapse hierarchy (Guéziec 2001, §4.2-4.3 with the priority process of
 * §3.2 and the coherence of §5.1): selective refinement of the base mesh by vertex splits.
 *
 * The queue holds the triangles of the current (partly refined) mesh keyed by their lower
 * bound d - ε, ε the largest current error at its corners (collapse_internal.h: they cover
 * the input). The front triangle is
 * refined: the split of its creator runs, after the splits it depends on ("split before",
 * performed in a topological order by a depth-first walk of the dependency DAG); the split
 * replaces its new triangles by the consumed ones, which enter the queue. Triangles a split
 * removes stay in the heap and are dropped when they reach the front (they are no longer
 * present). The first present, clean input triangle at the front is the closest.
 *
 * Coherence (§5.1): the cursor keeps the refined mesh and its queue between queries. A move of
 * the query by δ lowers every kept lower bound by at most δ; as in query.c the cursor adds δ
 * to a travelled distance and entries computed at an earlier travelled distance are "dirty"
 * and recomputed when they reach the front. It goes back to the base mesh ("substituted with
 * the base mesh", §4.2) when the query jumps farther than the last distance, when the last
 * query cost more than one from the base mesh, or when the queue grows far beyond that
 * (docs/sweep.md "Coherence"; the paper resets periodically, we reset when coherence stops
 * paying). A reset starts from a fixed start level: the base mesh with the last collapses
 * split again up to a few dozen triangles (start_level). A rigid motion of the mesh
 * (§5.2) is a move of the query carried into the mesh's frame (rigid.c's pose helpers); a
 * deformation (§5.3, collapse_deform.c) is caught up with before the next query (catch_up).
 *
 * Arrays only: the heap (one entry per hierarchy triangle at most, since a triangle enters
 * once per refinement from the base mesh), the done flags of the splits, the list of done
 * splits (to reset) and the walk's stack are allocated once per cursor. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "sweep/collapse_internal.h"
#include "sweep/sweep_heap.h"
#include "sweep/sweep_internal.h"

struct fl_sweep_collapse_cursor {
    const fl_sweep_collapse *h;
    fl_sweep_heap heap;
    uint8_t *done;      /* per split */
    double *cur;        /* per vertex: its current error (collapse_internal.h) */
    double *key;        /* per hierarchy triangle: its last key (valid once queued) */
    int groups;         /* lazy splits queue one group entry (split_run) */
    uint32_t *done_list; /* the done splits, to undo them on a reset */
    size_t done_count;
    uint32_t *stack; /* the dependency walk */
    double q[3];
    double travelled;
    double last_distance;
    size_t reset_cost, last_cost;
    int started;
    fl_vec stash; /* fl_sweep_entry: input triangles popped by a k-nearest / within query */
    size_t start_split; /* a reset starts from the base mesh with splits >= this one done */
    int have_ball;    /* §3.3: the last exact answer's ball is valid */
    double ball_r;    /* around q: within it, ball_leaf stays the closest */
    uint32_t ball_leaf;
    double moved_seen;     /* h->moved and h->updates when the cursor last caught up with */
    uint64_t updates_seen; /* the mesh's deformation (§5.3, collapse_deform.c) */
};

typedef struct query_state {
    double q[3];
    double slack;
    double upper;    /* best upper bound found (§3.2) */
    uint32_t best;   /* nearest input triangle evaluated, for early stops */
    double best_d;
    size_t visited;
    int want_upper; /* only tolerance queries use upper bounds (§3.2 early stop) */
} query_state;

static const double *vtx(const fl_sweep_collapse *h, uint32_t v)
{
    return h->xyz + 3 * (size_t)v;
}

static double tri_distance(const fl_sweep_collapse *h, uint32_t t, const double *q, double *bary,
                           double *point)
{
    const uint32_t *v = h->tri[t].v;
    return sqrt(fl_sweep_triangle_closest(q, vtx(h, v[0]), vtx(h, v[1]), vtx(h, v[2]), bary,
                                          point));
}

/* Computes triangle t's bounds at the current query and queues it (clean). The upper bound of
 * a coarse triangle is the distance to a vertex of an input triangle it stands for: d + ε
 * would need the triangle to lie within ε of the input too, which the ownership does
 * not promise (docs/sweep.md). */
static void visit(fl_sweep_collapse_cursor *c, query_state *st, uint32_t t)
{
    const fl_sweep_collapse *h = c->h;
    const fl_collapse_tri *x = h->tri + t;
    double bary[3], p[3];
    double d = tri_distance(h, t, st->q, bary, p), lo = d, hi = d;
    st->visited++;
    if (x->creator != FL_COLLAPSE_NONE) {
        lo = d - fl_collapse_eps(h, c->cur, t) - st->slack - 16 * DBL_EPSILON * c->travelled;
        hi = INFINITY;
        if (st->want_upper && x->rep != FL_COLLAPSE_NONE) {
            const double *r = vtx(h, x->rep);
            hi = sqrt((st->q[0] - r[0]) * (st->q[0] - r[0]) + (st->q[1] - r[1]) * (st->q[1] - r[1]) +
                      (st->q[2] - r[2]) * (st->q[2] - r[2])) +
                 st->slack;
        }
    } else if (d < st->best_d) {
        st->best_d = d;
        st->best = t;
    }
    if (hi < st->upper) st->upper = hi;
    c->key[t] = lo + c->travelled;
    fl_sweep_heap_push(&c->heap, (fl_sweep_entry){lo + c->travelled, c->travelled, t, 0});
}

#define LAZY (-1.0) /* the `base` of an entry whose distance is not computed yet (never equal
                     * to the travelled distance, which is >= 0) */

/* Runs split k: its new triangles leave the mesh (their heap entries go stale), u and v get
 * their errors before the collapse back, the triangles collapse k consumed come back and are
 * queued. With `lazy` (a split run only because another one depends on it) their distances
 * are not computed: they stand for the same input triangles as k's new ones, so the smallest
 * key among those is a valid lower bound for each of them. They are queued as one entry of
 * that key, node tri_count + k (a "group"), expanded only if it reaches the front (most never
 * do); if the node numbers would not fit in 32 bits, one dirty entry each (§5.1's
 * mechanism) instead. */
static void split_run(fl_sweep_collapse_cursor *c, query_state *st, uint32_t k, int lazy)
{
    const fl_sweep_collapse *h = c->h;
    double key = INFINITY;
    for (uint32_t t = h->new_start[k]; lazy && t < h->new_start[k + 1]; t++)
        key = fmin(key, c->key[t]); /* present, hence queued since the last reset */
    c->done[k] = 1;
    fl_collapse_split_errors(h, c->cur, k);
    c->done_list[c->done_count++] = k;
    for (uint32_t i = h->old_start[k]; i < h->old_start[k + 1]; i++) {
        uint32_t t = h->old[i];
        if (!lazy) {
            visit(c, st, t);
            continue;
        }
        c->key[t] = key;
        if (!c->groups) fl_sweep_heap_push(&c->heap, (fl_sweep_entry){key, LAZY, t, 0});
    }
    if (lazy && c->groups)
        fl_sweep_heap_push(&c->heap, (fl_sweep_entry){key, LAZY, (uint32_t)h->tri_count + k, 0});
}

/* A group entry at the front: its triangles still present are computed and queued. */
static void expand_group(fl_sweep_collapse_cursor *c, query_state *st, uint32_t k)
{
    const fl_sweep_collapse *h = c->h;
    for (uint32_t i = h->old_start[k]; i < h->old_start[k + 1]; i++)
        if (fl_collapse_present(h, c->done, h->old[i])) visit(c, st, h->old[i]);
}

/* Runs split k after the splits it needs, in a topological order of the dependency DAG (a
 * depth-first walk; dependencies point to later collapses, so the stack holds an increasing
 * path and never more than split_count entries). */
static void refine(fl_sweep_collapse_cursor *c, query_state *st, uint32_t k)
{
    size_t top = 0;
    c->stack[top++] = k;
    while (top > 0) {
        uint32_t j = c->stack[top - 1];
        if (c->done[j]) {
            top--;
            continue;
        }
        uint32_t d = fl_collapse_pending(c->h, c->done, j);
        if (d != FL_COLLAPSE_NONE) {
            c->stack[top++] = d;
            continue;
        }
        top--;
        split_run(c, st, j, j != k);
    }
}

static void reset_to_base(fl_sweep_collapse_cursor *c, query_state *st)
{
    const fl_sweep_collapse *h = c->h;
    for (size_t i = 0; i < c->done_count; i++) {
        const fl_collapse_split *x = h->split + c->done_list[i];
        c->done[c->done_list[i]] = 0;
        c->cur[x->u] = h->err_self[x->u];
        c->cur[x->v] = h->err_self[x->v];
    }
    c->done_count = 0;
    c->heap.n = 0;
    c->travelled = 0;
    c->started = 1;
    c->reset_cost = SIZE_MAX;
    for (size_t i = 0; i < c->h->base_count; i++)
        if (fl_collapse_present(h, c->done, h->base[i])) visit(c, st, h->base[i]);
    /* the start level: the last collapses split again, latest first (a topological order of
     * the "split before" DAG, whose edges point to later collapses) */
    for (size_t k = h->split_count; k-- > c->start_split;) {
        c->done[k] = 1;
        fl_collapse_split_errors(h, c->cur, (uint32_t)k);
        c->done_list[c->done_count++] = (uint32_t)k;
    }
    for (size_t k = c->start_split; k < h->split_count; k++)
        for (uint32_t i = h->old_start[k]; i < h->old_start[k + 1]; i++)
            if (fl_collapse_present(h, c->done, h->old[i])) visit(c, st, h->old[i]);
}

/* §5.3 before a query, after fl_sweep_collapse_update_vertices or _refit: the current errors
 * are those of the new tables, replayed in the order the done splits ran (a reset undoes them
 * back to err_self, so that order gives the state); every fine triangle moved by at most the
 * displacements summed since (widened for the rounding of the sums), so, as for a query move
 * (§5.1), the kept keys stay lower bounds once the travelled distance grows by that much and
 * go dirty. The §3.3 ball is forgotten. */
static void catch_up(fl_sweep_collapse_cursor *c)
{
    const fl_sweep_collapse *h = c->h;
    if (c->updates_seen == h->updates) return;
    memcpy(c->cur, h->err_self, h->vertex_count * sizeof *c->cur);
    for (size_t i = 0; i < c->done_count; i++)
        fl_collapse_split_errors(h, c->cur, c->done_list[i]);
    if (h->moved != c->moved_seen)
        c->travelled += h->moved - c->moved_seen + 4 * DBL_EPSILON * h->moved;
    c->have_ball = 0;
    c->moved_seen = h->moved;
    c->updates_seen = h->updates;
}

/* §5.1 bookkeeping before a query: account the move, or go back to the base mesh. */
static void advance(fl_sweep_collapse_cursor *c, query_state *st)
{
    double m2 = 0;
    for (int i = 0; i < 3; i++)
        m2 += (st->q[i] - c->q[i]) * (st->q[i] - c->q[i]);
    double move = sqrt(m2);
    int reset = !c->started || !(move <= c->last_distance) || c->last_cost > c->reset_cost ||
                c->heap.n > 8 * c->reset_cost + 64 + c->h->base_count;
    memcpy(c->q, st->q, sizeof c->q);
    c->have_ball = 0;
    if (reset) {
        reset_to_base(c, st);
    } else {
        c->travelled += move + st->slack;
    }
}

static void answer_exact(const fl_sweep_collapse *h, uint32_t t, const double *q, fl_closest *r)
{
    r->distance = tri_distance(h, t, q, r->bary, r->point);
    r->element = t; /* input triangles keep their index in the hierarchy */
    r->lower = r->upper = r->distance;
    r->exact = 1;
}

static void answer_interval(const fl_sweep_collapse *h, const query_state *st, double lower,
                            fl_closest *r)
{
    if (st->best != FL_COLLAPSE_NONE) {
        answer_exact(h, st->best, st->q, r);
    } else {
        r->element = FL_SWEEP_NONE;
        for (int i = 0; i < 3; i++)
            r->point[i] = r->bary[i] = NAN;
    }
    r->lower = lower > 0 ? lower : 0;
    r->upper = st->upper;
    r->distance = (r->lower + r->upper) / 2;
    r->exact = 0;
}

/* Starts a query at q3: the rounding slack and the §5.1 bookkeeping. */
static void query_begin(fl_sweep_collapse_cursor *c, query_state *st, const double *q3,
                        int want_upper)
{
    catch_up(c);
    *st = (query_state){{q3[0], q3[1], q3[2]}, 0, INFINITY, FL_COLLAPSE_NONE, INFINITY, 0,
                        want_upper};
    double m = fmax(fmax(fabs(q3[0]), fabs(q3[1])), fabs(q3[2]));
    st->slack = 64 * DBL_EPSILON * (c->h->scale + m);
    advance(c, st);
}

static void query_end(fl_sweep_collapse_cursor *c, const query_state *st, double distance)
{
    if (c->reset_cost == SIZE_MAX) c->reset_cost = st->visited;
    c->last_cost = st->visited;
    c->last_distance = distance;
}

#define FRONT_NONE FL_COLLAPSE_NONE       /* queue empty or front beyond the limit */
#define FRONT_TOLERANCE (FL_COLLAPSE_NONE - 1) /* the tolerance interval closed (§3.2) */

/* The priority process (§3.2, §4.3): refines the front triangle until a clean, present input
 * triangle is at the front and returns it (left queued, its exact distance is its key), or
 * FRONT_NONE once the front's lower bound exceeds `limit` (or the queue is empty), or
 * FRONT_TOLERANCE when tol > 0 and the best upper bound is within tol of the front's lower
 * bound. *lower gets the front's lower bound. */
static uint32_t front_leaf(fl_sweep_collapse_cursor *c, query_state *st, double limit, double tol,
                           double *lower)
{
    const fl_sweep_collapse *h = c->h;
    *lower = INFINITY;
    while (c->heap.n > 0) {
        fl_sweep_entry top = c->heap.e[0];
        if (top.node >= h->tri_count) {
            fl_sweep_heap_pop(&c->heap);
            expand_group(c, st, top.node - (uint32_t)h->tri_count);
            continue;
        }
        if (!fl_collapse_present(h, c->done, top.node)) { /* removed by a split */
            fl_sweep_heap_pop(&c->heap);
            continue;
        }
        if (top.base != c->travelled) { /* dirty (§5.1): recompute at this query */
            fl_sweep_heap_pop(&c->heap);
            visit(c, st, top.node);
            continue;
        }
        *lower = top.key - c->travelled;
        if (!(*lower <= limit)) return FRONT_NONE;
        if (top.node < h->fine_count) return top.node;
        if (tol > 0 && st->upper - *lower <= tol) return FRONT_TOLERANCE;
        fl_sweep_heap_pop(&c->heap);
        refine(c, st, h->tri[top.node].creator);
    }
    return FRONT_NONE;
}

/* §3.3 after an exact answer t at distance d (t at the heap's front): every other present
 * triangle is in the heap (with stale ones, whose keys only make this smaller) with a lower
 * bound >= the smaller key at positions 1 and 2, the second interval's lower end. A query
 * moved by less than half the gap keeps t as its closest triangle. */
static void set_ball(fl_sweep_collapse_cursor *c, const query_state *st, uint32_t t, double d)
{
    double second = INFINITY;
    for (size_t i = 1; i <= 2 && i < c->heap.n; i++)
        second = fmin(second, c->heap.e[i].key - c->travelled);
    double r = (second - d) / 2 - 2 * st->slack - 16 * DBL_EPSILON * c->travelled;
    c->have_ball = r > 0;
    c->ball_r = r;
    c->ball_leaf = t;
}

static void collapse_query(fl_sweep_collapse_cursor *c, const double *q3, double tol,
                           fl_closest *r)
{
    query_state st;
    query_begin(c, &st, q3, tol > 0);
    double lower;
    uint32_t t = front_leaf(c, &st, INFINITY, tol, &lower);
    if (t == FRONT_TOLERANCE || t == FRONT_NONE) {
        answer_interval(c->h, &st, lower, r);
    } else { /* (the base mesh covers a non-empty input: the queue never runs dry) */
        answer_exact(c->h, t, st.q, r);
        set_ball(c, &st, t, r->distance);
    }
    query_end(c, &st, r->distance);
    r->reused = 0;
    r->visited = st.visited;
}

/* §4.4: continues the priority process past the first leaf. Input triangles leave the front in
 * the order of their distances; each is reported through `emit` (which returns nonzero to
 * stop) while its distance is <= radius, then all of them are queued again, so the cursor's
 * queue still covers the input (§5.1). Returns -1 when out of memory. */
typedef int (*emit_fn)(void *user, uint32_t element, double distance);

static int collapse_ordered(fl_sweep_collapse_cursor *c, const double *q3, double radius,
                            emit_fn emit, void *user)
{
    query_state st;
    query_begin(c, &st, q3, 0);
    /* the keys of leaves are d + travelled in floating point: leaves a little beyond radius
     * are popped too (and not reported) so that none at distance <= radius is missed */
    double limit = radius + st.slack + 4 * DBL_EPSILON * c->travelled, lower, first = -1;
    int status = 0;
    c->stash.count = 0;
    for (;;) {
        uint32_t t = front_leaf(c, &st, limit, 0, &lower);
        if (t == FRONT_NONE) break;
        fl_sweep_entry x = fl_sweep_heap_pop(&c->heap);
        if (fl_vec_push(&c->stash, &x, 1)) {
            fl_sweep_heap_push(&c->heap, x);
            status = -1;
            break;
        }
        double bary[3], p[3], d = tri_distance(c->h, t, st.q, bary, p);
        if (first < 0) first = d;
        if (d <= radius && emit(user, t, d)) break;
    }
    for (size_t i = 0; i < c->stash.count; i++)
        fl_sweep_heap_push(&c->heap, ((fl_sweep_entry *)c->stash.data)[i]);
    query_end(c, &st, first >= 0 ? first : fmax(0, lower < INFINITY ? lower : 0));
    return status;
}

/* The reset's start level (ours, for speed; §4.2 resets to the base mesh): from a base mesh of
 * a few triangles every query first splits the top of the hierarchy, whose errors are of the
 * mesh's size, so the split bookkeeping to get there is paid again at each reset. A reset
 * therefore also redoes the last collapses' splits, latest first, while the mesh stays within
 * START_LEVEL_TRIANGLES triangles. Measured (docs/sweep.md): about 10 % fewer distances and
 * 5-12 % less CPU on random and near queries of the npm bunny and armadillo; larger levels cost
 * more than they save (1024: twice the distances), and so does 64 on meshes of a few hundred
 * triangles (the tests' open grid: 32 175 distances for 300 fresh queries against 21 675 from
 * the base mesh), hence at most one triangle per 50 input ones. Returns the first split of
 * that level. */
#define START_LEVEL_TRIANGLES 64

static size_t start_level(const fl_sweep_collapse *h)
{
    size_t m = h->base_count, k = h->split_count, most = h->fine_count / 50;
    if (most > START_LEVEL_TRIANGLES) most = START_LEVEL_TRIANGLES;
    while (k > 0) { /* split k-1 replaces its new triangles by the ones it consumed */
        size_t grow = (h->old_start[k] - h->old_start[k - 1]) -
                      (size_t)(h->new_start[k] - h->new_start[k - 1]);
        if (m + grow > most) break;
        m += grow;
        k--;
    }
    return k;
}

fl_status fl_sweep_collapse_cursor_new(const fl_sweep_collapse *hierarchy,
                                       fl_sweep_collapse_cursor **out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "output pointer is NULL");
    *out = NULL;
    if (!hierarchy) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "collapse hierarchy is NULL");
    fl_sweep_collapse_cursor *c = calloc(1, sizeof *c);
    size_t ns = hierarchy->split_count ? hierarchy->split_count : 1;
    if (c) {
        c->h = hierarchy;
        fl_vec_init(&c->stash, sizeof(fl_sweep_entry));
        /* every triangle at most once, plus one group entry per split */
        c->groups = hierarchy->tri_count + hierarchy->split_count < UINT32_MAX;
        c->heap.e = fl_alloc_array(hierarchy->tri_count + hierarchy->split_count,
                                   sizeof *c->heap.e);
        c->key = fl_alloc_array(hierarchy->tri_count, sizeof *c->key);
        c->done = calloc(ns, 1);
        c->done_list = fl_alloc_array(ns, sizeof *c->done_list);
        c->stack = fl_alloc_array(ns, sizeof *c->stack);
        c->cur = fl_alloc_array(hierarchy->vertex_count ? hierarchy->vertex_count : 1,
                                sizeof *c->cur);
        if (c->cur)
            memcpy(c->cur, hierarchy->err_self, hierarchy->vertex_count * sizeof *c->cur);
        c->start_split = start_level(hierarchy);
        c->moved_seen = hierarchy->moved;
        c->updates_seen = hierarchy->updates;
    }
    if (!c || !c->heap.e || !c->done || !c->done_list || !c->stack || !c->cur ||
        !c->key) {
        fl_sweep_collapse_cursor_free(c);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for a collapse cursor");
    }
    *out = c;
    return FL_OK;
}

void fl_sweep_collapse_cursor_free(fl_sweep_collapse_cursor *cursor)
{
    if (!cursor) return;
    free(cursor->heap.e);
    free(cursor->done);
    free(cursor->done_list);
    free(cursor->stack);
    free(cursor->cur);
    free(cursor->key);
    fl_vec_free(&cursor->stash);
    free(cursor);
}

void fl_sweep_collapse_cursor_reset(fl_sweep_collapse_cursor *cursor)
{
    if (!cursor) return;
    cursor->started = 0; /* the next query starts from the base mesh (advance) */
    cursor->have_ball = 0;
}

static fl_status check_query(const double *q, fl_error *err)
{
    for (int i = 0; i < 3; i++)
        if (!fl_sweep_coord_ok(q[i]))
            return fl_fail(err, FL_ERR_USAGE, NULL, -1, "query point is not finite or beyond 1e150");
    return FL_OK;
}

fl_status fl_sweep_collapse_cursor_closest(fl_sweep_collapse_cursor *cursor, const double *q,
                                           double tolerance, fl_closest *result, fl_error *err)
{
    if (!cursor || !q || !result)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "cursor, query and result must not be NULL");
    if (!(tolerance >= 0)) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "tolerance must be >= 0");
    fl_status st = check_query(q, err);
    if (st != FL_OK) return st;
    catch_up(cursor);
    if (cursor->have_ball) { /* §3.3: the cursor's state stays that of the ball's centre */
        double d2 = 0;
        for (int i = 0; i < 3; i++)
            d2 += (q[i] - cursor->q[i]) * (q[i] - cursor->q[i]);
        if (sqrt(d2) < cursor->ball_r) {
            answer_exact(cursor->h, cursor->ball_leaf, q, result);
            result->reused = 1;
            result->visited = 1;
            return FL_OK;
        }
    }
    collapse_query(cursor, q, tolerance, result);
    return FL_OK;
}

/* §5.2: "for a rigid motion of the mesh the sizes of the intervals are affected, but the
 * bounding-volume hierarchy is not". The query is carried into the mesh's frame (rigid.c's
 * helpers, shared with the spatial cursor), so a moving mesh is a moving query for the cursor:
 * δ is the move of the carried query, intervals widen by it and fronts are recomputed (§5.1). */
fl_status fl_sweep_collapse_cursor_closest_posed(fl_sweep_collapse_cursor *cursor,
                                                 const fl_sweep_pose *pose, const double *q,
                                                 double tolerance, fl_closest *result,
                                                 fl_error *err)
{
    if (!cursor || !pose || !q || !result)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "cursor, pose, query and result must not be NULL");
    fl_status st = fl_sweep_pose_check(3, pose, err);
    if (st != FL_OK) return st;
    double local[3];
    if (!fl_sweep_pose_to_local(3, pose, q, local))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "query point is not finite or beyond 1e150");
    st = fl_sweep_collapse_cursor_closest(cursor, local, tolerance, result, err);
    if (st == FL_OK) fl_sweep_pose_to_world(pose, result);
    return st;
}

typedef struct knearest_out {
    uint32_t *element;
    double *distance;
    size_t k, found;
} knearest_out;

static int emit_knearest(void *user, uint32_t element, double distance)
{
    knearest_out *o = user;
    size_t i = o->found++;
    o->element[i] = element, o->distance[i] = distance;
    return o->found >= o->k; /* k > 0 here */
}

fl_status fl_sweep_collapse_cursor_knearest(fl_sweep_collapse_cursor *cursor, const double *q,
                                            size_t k, uint32_t *elements, double *distances,
                                            size_t *found, fl_error *err)
{
    if (!cursor || !q || !found || (k > 0 && (!elements || !distances)))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "cursor, query and outputs must not be NULL");
    *found = 0;
    fl_status st = check_query(q, err);
    if (st != FL_OK || k == 0) return st;
    knearest_out o = {elements, distances, k, 0};
    if (collapse_ordered(cursor, q, INFINITY, emit_knearest, &o))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for a k-nearest query");
    *found = o.found;
    return FL_OK;
}

typedef struct within_out {
    fl_vec element, distance;
    int failed;
} within_out;

static int emit_within(void *user, uint32_t element, double distance)
{
    within_out *o = user;
    o->failed = fl_vec_push(&o->element, &element, 1) || fl_vec_push(&o->distance, &distance, 1);
    return o->failed;
}

fl_status fl_sweep_collapse_cursor_within(fl_sweep_collapse_cursor *cursor, const double *q,
                                          double radius, fl_sweep_hits *out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "output must not be NULL");
    *out = (fl_sweep_hits){0, NULL, NULL};
    if (!cursor || !q) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "cursor and query must not be NULL");
    if (!(radius >= 0)) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "radius must be >= 0");
    fl_status st = check_query(q, err);
    if (st != FL_OK) return st;
    within_out o = {.failed = 0};
    fl_vec_init(&o.element, sizeof(uint32_t));
    fl_vec_init(&o.distance, sizeof(double));
    int nomem = collapse_ordered(cursor, q, radius, emit_within, &o) || o.failed;
    size_t n = o.element.count;
    if (!nomem && n == 0) { /* a zeroed struct is "no hits"; allocate as fl_sweep_within does */
        nomem = fl_vec_reserve(&o.element, 1) || fl_vec_reserve(&o.distance, 1);
    }
    out->element = fl_vec_release(&o.element);
    out->distance = fl_vec_release(&o.distance);
    if (nomem || !out->element || !out->distance) {
        fl_sweep_hits_free(out);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the hits of a query");
    }
    out->count = n;
    return FL_OK;
}

/* Runs one query through a temporary cursor (the hierarchy itself is never changed). */
fl_status fl_sweep_collapse_knearest(const fl_sweep_collapse *hierarchy, const double *q, size_t k,
                                     uint32_t *elements, double *distances, size_t *found,
                                     fl_error *err)
{
    if (found) *found = 0;
    fl_sweep_collapse_cursor *c;
    fl_status st = fl_sweep_collapse_cursor_new(hierarchy, &c, err);
    if (st == FL_OK)
        st = fl_sweep_collapse_cursor_knearest(c, q, k, elements, distances, found, err);
    fl_sweep_collapse_cursor_free(c);
    return st;
}

fl_status fl_sweep_collapse_within(const fl_sweep_collapse *hierarchy, const double *q,
                                   double radius, fl_sweep_hits *out, fl_error *err)
{
    if (out) *out = (fl_sweep_hits){0, NULL, NULL};
    fl_sweep_collapse_cursor *c;
    fl_status st = fl_sweep_collapse_cursor_new(hierarchy, &c, err);
    if (st == FL_OK) st = fl_sweep_collapse_cursor_within(c, q, radius, out, err);
    fl_sweep_collapse_cursor_free(c);
    return st;
}

fl_status fl_sweep_collapse_closest(const fl_sweep_collapse *hierarchy, const double *q, size_t nq,
                                    double tolerance, fl_closest *results, fl_error *err)
{
    if (nq == 0) return FL_OK;
    if (!q || !results)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "queries and results must not be NULL");
    fl_sweep_collapse_cursor *c;
    fl_status st = fl_sweep_collapse_cursor_new(hierarchy, &c, err);
    for (size_t i = 0; i < nq && st == FL_OK; i++)
        st = fl_sweep_collapse_cursor_closest(c, q + 3 * i, tolerance, results + i, err);
    fl_sweep_collapse_cursor_free(c);
    return st;
}

fl_status fl_sweep_collapse_info_get(const fl_sweep_collapse *hierarchy,
                                     fl_sweep_collapse_info *info, fl_error *err)
{
    if (!hierarchy || !info)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hierarchy and info must not be NULL");
    const fl_sweep_collapse *h = hierarchy;
    size_t ns = h->split_count ? h->split_count : 1;
    info->fine_triangles = h->fine_count;
    info->base_triangles = h->base_count;
    info->splits = h->split_count;
    info->triangles = h->tri_count;
    info->bytes = fl_collapse_bytes(h);
    info->cursor_bytes = sizeof(fl_sweep_collapse_cursor) +
                         (h->tri_count + h->split_count) * sizeof(fl_sweep_entry) +
                         ns * (1 + 2 * sizeof(uint32_t)) + h->vertex_count * sizeof(double) +
                         h->tri_count * sizeof(double);
    return FL_OK;
}
