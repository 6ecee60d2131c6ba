/* Closest-point queries: the priority process of §3.2 on intervals [d - ε, d + ε] keyed by
 * d - ε, shared by polylines and meshes (§4.2: "nothing else is changed in the priority
 * structure"), with the early stop on a tolerance, the constant-time coherence ball of §3.3
 * and the small-motion update of §5.1.
 *
 * The cursor keeps its queue between queries (§5.1). The queue always holds a cut of the
 * hierarchy — regions that together cover the shape — so regions are never pruned, only left
 * at the back. When the query point moves by δ every interval widens by δ on both sides; the
 * priorities do not change, so instead of touching the queue the cursor adds δ to the distance
 * it has travelled, and an entry's current lower bound is key - (travelled - base). An entry
 * whose base is not the current travelled distance is "dirty": when it reaches the front its
 * distance is recomputed. The first clean leaf at the front is the closest element.
 *
 * Rounding: lower bounds are lowered and upper bounds raised by a slack of 64 ulps of the
 * largest coordinate involved, so rounding never lets a nearer region stay behind. */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "core/core.h"
#include "sweep/sweep_heap.h"
#include "sweep/sweep_internal.h"

struct fl_sweep_cursor {
    const fl_sweep *s;
    fl_sweep_heap h;
    double q[3];          /* the last query */
    double travelled;     /* sum of the query's moves since the queue was reset (§5.1) */
    size_t reset_cost;    /* distances computed by the last query that started from the root */
    size_t last_cost;     /* distances computed by the last query */
    double last_distance; /* the last query's distance (or interval midpoint) */
    int started;          /* the queue holds a cut of the hierarchy */
    int have_ball;        /* §3.3: the last exact answer's ball is valid */
    double center[3];
    double radius;
    uint32_t leaf; /* the node that is closest anywhere inside the ball */
    uint32_t last_leaf; /* the last exact answer's leaf, or FL_SWEEP_LEAF */
    /* Entries queued beyond the current query's best upper bound wait unsorted at the end of
     * the heap's array (e[node_count - 1 - i], i < back_n), out of the heap's way: a query
     * from the root queues most of the hierarchy there and never needs it, yet the queue stays
     * a cut for §5.1. back_min is their smallest key; they join the heap before it could
     * matter (pending). */
    size_t back_n;
    double back_min;
    double moved_seen;     /* s->moved and s->updates when the queue was last brought up */
    uint64_t updates_seen; /* to date with the shape's motion (§5.2, §5.3) */
    fl_sweep_walk walk;    /* the certified region of coherent streams (walk.c) */
    uint32_t *stack;       /* the walk region's search stack, one slot a node */
    double walk_reach;     /* the next region's reach in steps (walk_step) */
    size_t boxes;          /* box distances computed, all queries (statistics for tests) */
};

static void fill_leaf(const fl_sweep *s, uint32_t leaf, const double *q3, fl_closest *r)
{
    const fl_sweep_node *node = s->nodes + leaf;
    r->distance = fl_sweep_node_distance(s, node, q3, r->bary, r->point);
    r->element = node->element;
    r->lower = r->upper = r->distance;
    r->exact = 1;
}

/* The state of one query. */
typedef struct search {
    double upper; /* best upper bound computed in this query (§3.2) */
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

/* Queues an entry: into the heap if it may hold this query's answer, else at the back. With
 * `replace`, the entry takes the place of the heap's front (which the caller has consumed). */
static void enqueue(fl_sweep_cursor *cur, const search *st, fl_sweep_entry e, int replace)
{
    if (e.key - cur->travelled <= st->upper) {
        if (replace)
            fl_sweep_heap_replace_top(&cur->h, e);
        else
            fl_sweep_heap_push(&cur->h, e);
        return;
    }
    if (replace) fl_sweep_heap_pop(&cur->h);
    cur->h.e[cur->s->node_count - 1 - cur->back_n++] = e;
    if (e.key < cur->back_min) cur->back_min = e.key;
}

/* Moves the back into the heap when its smallest key could reach the front. */
static void pending(fl_sweep_cursor *cur)
{
    if (cur->back_n == 0 || (cur->h.n > 0 && cur->h.e[0].key < cur->back_min)) return;
    size_t end = cur->s->node_count;
    for (size_t i = 0; i < cur->back_n; i++)
        fl_sweep_heap_push(&cur->h, cur->h.e[end - 1 - i]);
    cur->back_n = 0;
    cur->back_min = INFINITY;
}

/* Computes a region's interval at the current query and queues it (clean). With boxes
 * (boxes.c) the box distance comes first: a region whose box is already beyond the best upper
 * bound cannot hold this query's answer, so it is queued on its box bound alone ("partial")
 * and its element is measured only if it ever reaches the front. `full` forces the element;
 * `replace`: the result takes the place of the heap's front (a pop and a push in one). */
static void visit(fl_sweep_cursor *cur, search *st, const double *q3, uint32_t id, int full,
                  int replace)
{
    const fl_sweep *s = cur->s;
    const fl_sweep_node *node = s->nodes + id;
    /* The key lo + travelled, and its difference with a later travelled, round at the scale
     * of the travelled distance: widen for that too. */
    double widen = st->slack + 16 * DBL_EPSILON * cur->travelled;
    double box_lo = -INFINITY;
    if (s->box) {
        box_lo = sqrt(fl_sweep_box_dist2(s->box[id].b, q3)) - widen;
        cur->boxes++;
        /* An internal region too goes on its box alone (issue #9): splitting it when it
         * reaches the front costs two box distances, its swept element a point-triangle solve
         * that on the bench streams paid for itself less often than the split (distances per
         * query fell 62 -> 22 on the npm bunny's random stream, 26 -> 6 near the surface). Its
         * upper bound still comes from the vertex inside it (upper_bound). */
        if (!full && !fl_sweep_is_leaf(node)) {
            if (s->triangles) {
                double hi = upper_bound(s, node, q3, 0, st->slack);
                if (hi < st->upper) st->upper = hi;
            }
            enqueue(cur, st, (fl_sweep_entry){box_lo + cur->travelled, cur->travelled, id, 1},
                    replace);
            return;
        }
        if (!full && box_lo > st->upper) {
            enqueue(cur, st, (fl_sweep_entry){box_lo + cur->travelled, cur->travelled, id, 1},
                    replace);
            return;
        }
    }
    double bary[3], c[3];
    double d = fl_sweep_node_distance(s, node, q3, bary, c);
    st->visited++;
    double lo = d, hi = d;
    if (!fl_sweep_is_leaf(node)) {
        lo = d - node->eps - widen;
        lo = lo > box_lo ? lo : box_lo;
        hi = upper_bound(s, node, q3, d, st->slack);
    } else if (d < st->best_leaf_d) {
        st->best_leaf_d = d;
        st->best_leaf = id;
    }
    if (hi < st->upper) st->upper = hi;
    enqueue(cur, st, (fl_sweep_entry){lo + cur->travelled, cur->travelled, id, 0}, replace);
}

/* The current lower bound of a queued region (§5.1: widened by the moves since its base). */
static double current_lower(const fl_sweep_cursor *cur, const fl_sweep_entry *e)
{
    return e->key - cur->travelled;
}

/* §3.3: no other region can come nearer than the second interval's lower end, so within half
 * the gap the answer keeps its element. The second smallest key of a heap is at 1 or 2. */
static void set_ball(fl_sweep_cursor *cur, const search *st, const double *q3, uint32_t leaf,
                     double d)
{
    double second = INFINITY;
    for (size_t i = 1; i <= 2 && i < cur->h.n; i++)
        second = fmin(second, current_lower(cur, cur->h.e + i));
    if (cur->back_n > 0) second = fmin(second, cur->back_min - cur->travelled);
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

/* §5.2/§5.3: the shape moved by at most this much (its largest vertex displacement, summed
 * over the updates since the queue was last brought up, widened for the rounding of the sums)
 * since the kept intervals were computed; like a move of the query, it widens them all. */
static double shape_motion(const fl_sweep_cursor *cur)
{
    if (cur->updates_seen == cur->s->updates) return 0;
    return cur->s->moved - cur->moved_seen + 4 * DBL_EPSILON * cur->s->moved;
}

/* Starts over from the root ("the mesh is substituted with the base mesh", §4.2) when the
 * kept queue is unlikely to pay: the query jumped farther than the last distance (so most of
 * the queue would be dirty), the last query cost more than one from the root, or the queue
 * has grown far beyond what a query from the root needs. Otherwise accounts the move (§5.1).
 * On a reset the root is queued, unless `no_root`: the caller searches from the root itself. */
static int advance(fl_sweep_cursor *cur, const double *q3, search *st, int no_root)
{
    double d2 = 0;
    for (int c = 0; c < 3; c++)
        d2 += (q3[c] - cur->q[c]) * (q3[c] - cur->q[c]);
    int reset = !cur->started || sqrt(d2) > cur->last_distance ||
                cur->last_cost > cur->reset_cost ||
                cur->h.n + cur->back_n > 8 * cur->reset_cost + 64;
    cur->travelled = reset ? 0 : cur->travelled + sqrt(d2) + shape_motion(cur) + st->slack;
    cur->moved_seen = cur->s->moved;
    cur->updates_seen = cur->s->updates;
    for (int c = 0; c < 3; c++)
        cur->q[c] = q3[c];
    if (!reset) return 0;
    cur->h.n = 0;
    cur->back_n = 0;
    cur->back_min = INFINITY;
    cur->started = 1;
    cur->reset_cost = SIZE_MAX;
    if (!no_root) visit(cur, st, q3, 0, 1, 0);
    return 1;
}

/* A first upper bound for a query on the kept queue (§5.1): the distance to the last answer's
 * element, near for a coherent walk. Every dirty region whose box is beyond it then costs a box
 * distance instead of an element solve when it comes to the front. */
static void seed_upper(fl_sweep_cursor *cur, search *st, const double *q3)
{
    if (cur->last_leaf == FL_SWEEP_LEAF) return;
    double bary[3], c[3];
    double d = fl_sweep_node_distance(cur->s, cur->s->nodes + cur->last_leaf, q3, bary, c);
    st->visited++;
    st->upper = d + st->slack;
    st->best_leaf = cur->last_leaf;
    st->best_leaf_d = d;
}

/* A first upper bound for a query from the root: follow the nearer box down to one leaf (a
 * few box distances) and take that element's distance, so that from the first split on every
 * region whose box lies beyond it is queued without an element solve (issue #9; the role of
 * CGAL's closest-vertex hint, without a separate search structure). */
static void seed_descent(fl_sweep_cursor *cur, search *st, const double *q3)
{
    const fl_sweep *s = cur->s;
    if (!s->box) return;
    uint32_t id = 0;
    while (!fl_sweep_is_leaf(s->nodes + id)) {
        uint32_t a = s->nodes[id].child[0], b = s->nodes[id].child[1];
        double da = fl_sweep_box_dist2(s->box[a].b, q3);
        double db = fl_sweep_box_dist2(s->box[b].b, q3);
        cur->boxes += 2;
        id = db < da ? b : a;
    }
    double bary[3], c[3];
    double d = fl_sweep_node_distance(s, s->nodes + id, q3, bary, c);
    st->visited++;
    if (d + st->slack < st->upper) st->upper = d + st->slack;
    st->best_leaf = id;
    st->best_leaf_d = d;
}

/* The cut of a depth-first query (below): an entry at the back of the heap's array. */
static void dfs_cut(fl_sweep_cursor *cur, fl_sweep_entry e)
{
    cur->h.e[cur->s->node_count - 1 - cur->back_n++] = e;
}

/* An exact query from the root (issue #9, random queries on small meshes): branch and bound
 * depth first on the boxes alone, as CGAL's AABB tree does, instead of the priority process.
 * Far from the shape almost every region is decided by its box (a few flops on squared
 * distances), and a best-first queue paid a heap sift and an element solve (§4.1's swept
 * triangle) per region on top: on the npm bunny's random stream the queue and the internal
 * elements were about three quarters of the time. The nearer child goes first, so the first
 * leaf reached is the seed descent's, and every later leaf or region whose box lies beyond the
 * best distance so far (+ the rounding slack on both sides, as visit's test) is cut.
 *
 * The queue is still left as a cut of the hierarchy for §5.1 and §3.3: every cut region and
 * measured leaf is queued at the back with its lower bound (box distance − slack, "partial":
 * its element is measured if it reaches the front; a leaf's own distance, clean), the answer
 * alone in the heap. The search stack lives at the front of the same array: a node is at most
 * once on the stack or in the cut, so both fit in node_count slots. */
static void dfs_query(fl_sweep_cursor *cur, search *st, const double *q3, fl_closest *r)
{
    const fl_sweep *s = cur->s;
    fl_sweep_entry *e = cur->h.e;
    double best = INFINITY, lim2 = INFINITY, bary[3] = {0}, point[3] = {0};
    size_t best_pos = 0, top = 0;
    int found = 0;
    e[top++] = (fl_sweep_entry){fl_sweep_box_dist2(s->box[0].b, q3), 0, 0, 1};
    cur->boxes++;
    while (top > 0) {
        fl_sweep_entry x = e[--top]; /* key: the squared box distance */
        if (x.key > lim2) {
            dfs_cut(cur, (fl_sweep_entry){sqrt(x.key) - st->slack, 0, x.node, 1});
            continue;
        }
        const fl_sweep_box *box = s->box + x.node; /* in cache: its distance was just taken */
        if (box->child[0] == FL_SWEEP_LEAF) {
            double b[3], c[3];
            double d = fl_sweep_node_distance(s, s->nodes + x.node, q3, b, c);
            st->visited++;
            dfs_cut(cur, (fl_sweep_entry){d, 0, x.node, 0});
            if (d < best || !found) { /* the first leaf always: a NaN must not leave none */
                found = 1;
                best = d;
                best_pos = s->node_count - cur->back_n;
                lim2 = (d + 2 * st->slack) * (d + 2 * st->slack);
                for (int k = 0; k < 3; k++)
                    bary[k] = b[k], point[k] = c[k];
            }
            continue;
        }
        uint32_t near = box->child[0], far = box->child[1];
        double dn = fl_sweep_box_dist2(s->box[near].b, q3);
        double df = fl_sweep_box_dist2(s->box[far].b, q3);
        cur->boxes += 2;
        if (df < dn) {
            uint32_t t = near;
            near = far, far = t;
            double u = dn;
            dn = df, df = u;
        }
        /* Popped in order: the nearer on top; each is tested against the bound when popped. */
        e[top++] = (fl_sweep_entry){df, 0, far, 1};
        e[top++] = (fl_sweep_entry){dn, 0, near, 1};
    }
    /* The answer to the heap, the rest stays at the back with its smallest key. */
    fl_sweep_entry ans = e[best_pos];
    e[best_pos] = e[s->node_count - cur->back_n--];
    e[0] = ans;
    cur->h.n = 1;
    cur->back_min = INFINITY;
    for (size_t i = 0; i < cur->back_n; i++)
        cur->back_min = fmin(cur->back_min, e[s->node_count - 1 - i].key);
    r->distance = r->lower = r->upper = best;
    r->element = s->nodes[ans.node].element;
    r->exact = 1;
    for (int k = 0; k < 3; k++)
        r->bary[k] = bary[k], r->point[k] = point[k];
    set_ball(cur, st, q3, ans.node, best);
    cur->last_leaf = ans.node;
}

/* The priority process (§3.2) on the kept queue: refresh dirty fronts, split clean internal
 * fronts; the first clean leaf at the front is the answer, or stop once the interval fits the
 * tolerance. The answer stays queued for the next query. */
static void sweep_query(fl_sweep_cursor *cur, const double *q3, double tol, fl_closest *r)
{
    const fl_sweep *s = cur->s;
    search st = {INFINITY, FL_SWEEP_LEAF, INFINITY, fl_sweep_query_slack(s, q3), 0};
    fl_sweep_heap *h = &cur->h;
    cur->have_ball = 0;
    int dfs = tol == 0 && s->box;
    if (advance(cur, q3, &st, dfs)) {
        if (dfs) {
            dfs_query(cur, &st, q3, r);
            goto done;
        }
        seed_descent(cur, &st, q3);
    } else {
        seed_upper(cur, &st, q3);
    }
    for (;;) {
        pending(cur);
        fl_sweep_entry top = h->e[0];
        const fl_sweep_node *node = s->nodes + top.node;
        int clean = top.base == cur->travelled;
        /* A clean region known by its box alone is split like any other (visit); a leaf known
         * by its box is measured. */
        if (!clean || (top.partial && fl_sweep_is_leaf(node))) {
            visit(cur, &st, q3, top.node, clean, 1);
            continue;
        }
        if (fl_sweep_is_leaf(node)) {
            fill_leaf(s, top.node, q3, r);
            set_ball(cur, &st, q3, top.node, r->distance);
            cur->last_leaf = top.node;
            break;
        }
        if (tol > 0 && st.upper - current_lower(cur, &top) <= tol) {
            approximate(s, &st, current_lower(cur, &top), q3, r);
            break;
        }
        visit(cur, &st, q3, node->child[0], 0, 1);
        visit(cur, &st, q3, node->child[1], 0, 0);
    }
done:
    if (cur->reset_cost == SIZE_MAX) cur->reset_cost = st.visited;
    cur->last_cost = st.visited;
    cur->last_distance = r->distance;
    r->reused = 0;
    r->visited = st.visited;
}

/* A coherent stream (a step below WALK_FRACTION of the last distance: the bench walk's steps
 * are 1/20 to 1/100 of it, random streams' steps larger than it; at 1/2 the random bench
 * streams built rare regions over thick shells, +9 % distances) goes through the walk region
 * (walk.c): answered inside the current one when certified, else from a new one around the
 * query, built for moves of WALK_REACH steps (2 measured best on the bench walk: 1 rebuilds
 * too often, 4 and more keep too many members). The kept queue is not brought along (that is
 * what makes a step cheap), so the next query through the queue starts from the root. */
#define WALK_FRACTION 0.125
#define WALK_REACH 2.0
#define WALK_REACH_MAX 64.0
#define WALK_FEW 6
#define WALK_MANY 24

static int walk_step(fl_sweep_cursor *cur, const double *q3, fl_closest *r)
{
    const fl_sweep *s = cur->s;
    if (cur->last_leaf == FL_SWEEP_LEAF) return 0;
    /* The shape moved since the last query (§5.2/§5.3 updates): a region dies with every
     * update and rebuilding it from the root each step cost four times the kept queue, which
     * widens its intervals by the motion instead (test_sweep_polyline_motion's walk). */
    if (cur->updates_seen != s->updates) return 0;
    double d2 = 0;
    for (int c = 0; c < 3; c++)
        d2 += (q3[c] - cur->q[c]) * (q3[c] - cur->q[c]);
    double step = sqrt(d2);
    if (!(step <= WALK_FRACTION * cur->last_distance)) return 0;
    if (!fl_sweep_walk_answer(s, &cur->walk, q3, r)) {
        if (cur->walk_reach < WALK_REACH) cur->walk_reach = WALK_REACH;
        /* A reach beyond a quarter of the distance would sweep a thick shell of the shape. */
        double reach = fmin(cur->walk_reach * step, 0.25 * cur->last_distance);
        if (!fl_sweep_walk_build(s, &cur->walk, q3, reach, cur->last_leaf, cur->stack, r))
            return 0;
        /* Few members: a wider region is cheap to check and lives longer; many: narrower. */
        if (cur->walk.n < WALK_FEW && cur->walk_reach < WALK_REACH_MAX) cur->walk_reach *= 2;
        if (cur->walk.n > WALK_MANY && cur->walk_reach > WALK_REACH) cur->walk_reach /= 2;
    }
    for (int c = 0; c < 3; c++)
        cur->q[c] = q3[c];
    cur->last_distance = r->distance;
    cur->last_leaf = cur->walk.answer;
    cur->started = 0; /* so the queue's motion bookkeeping may restart with this shape state */
    cur->updates_seen = s->updates;
    cur->moved_seen = s->moved;
    /* §3.3's ball from the region's second-nearest bound, as set_ball does from the heap. */
    double radius = (cur->walk.second - r->distance) / 2 - fl_sweep_query_slack(s, q3);
    cur->have_ball = radius > 0;
    cur->radius = radius;
    cur->leaf = cur->walk.answer;
    for (int c = 0; c < 3; c++)
        cur->center[c] = q3[c];
    return 1;
}

size_t fl_sweep_cursor_box_tests(const fl_sweep_cursor *cursor)
{
    return cursor->boxes + cursor->walk.boxes;
}

void fl_sweep_cursor_walk_stats(const fl_sweep_cursor *cursor, size_t *answered, size_t *built,
                                size_t *trimmed)
{
    *answered = cursor->walk.answered;
    *built = cursor->walk.built;
    *trimmed = cursor->walk.trimmed;
}

fl_status fl_sweep_cursor_new(const fl_sweep *sweep, fl_sweep_cursor **out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "output pointer is NULL");
    *out = NULL;
    if (!sweep) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "sweep hierarchy is NULL");
    fl_sweep_cursor *cur = calloc(1, sizeof *cur);
    fl_sweep_entry *e = fl_alloc_array(sweep->node_count, sizeof *e);
    uint32_t *stack = fl_alloc_array(sweep->node_count, sizeof *stack);
    if (!cur || !e || !stack) {
        free(cur);
        free(e);
        free(stack);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for a sweep cursor");
    }
    cur->s = sweep;
    cur->h.e = e;
    cur->stack = stack;
    cur->last_leaf = FL_SWEEP_LEAF;
    *out = cur;
    return FL_OK;
}

const fl_sweep *fl_sweep_cursor_sweep(const fl_sweep_cursor *cursor)
{
    return cursor->s;
}

void fl_sweep_cursor_free(fl_sweep_cursor *cursor)
{
    if (!cursor) return;
    free(cursor->h.e);
    free(cursor->stack);
    free(cursor);
}

fl_status fl_sweep_cursor_closest(fl_sweep_cursor *cursor, const double *q, double tolerance,
                                  fl_closest *result, fl_error *err)
{
    double q3[3];
    if (!cursor || !q || !result)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "cursor, query and result must not be NULL");
    if (!(tolerance >= 0)) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "tolerance must be >= 0");
    if (!fl_sweep_lift_query(cursor->s, q, q3))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "query point is not finite or beyond 1e150");
    if (cursor->have_ball && cursor->updates_seen == cursor->s->updates) {
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
    if (tolerance == 0 && walk_step(cursor, q3, result)) return FL_OK;
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
