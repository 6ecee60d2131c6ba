/* The walk region: a certified "answer cannot change" region for coherent query streams
 * (issue #9), generalising the constant-time ball of §3.3.
 *
 * §3.3 keeps the ball of radius (d₂ − ε₂ − d₁)/2 around a query: inside it the first element
 * stays the closest. On a closed mesh the closest point is usually on an edge or a vertex
 * shared by several triangles, which are then equidistant, d₂ − ε₂ = d₁ and the ball is empty.
 * The walk region instead keeps every leaf whose distance at the centre c is below a threshold
 * T (the members) and the smallest lower bound B ≥ T of everything else in the hierarchy (the
 * regions pruned by the search and the leaves beyond T). For a query q at t = |q − c|, a region
 * outside the members is at least B − t away (the distance is 1-Lipschitz, the §5.1 widening
 * by δ); so the nearest member is the exact answer whenever its distance is at most B − t. Near
 * ties among the members are no obstacle: they are all measured. A member i cannot beat the
 * best distance m found so far once d_i(c) − t > m, so the members are kept in ascending d_i(c)
 * and measured only while that lower bound is below m — on a smooth walk the few members tied
 * with the answer.
 *
 * Rounding: distances at c carry an error below the slack of fl_sweep_query_slack(c), those at
 * q below slack(q); every bound is lowered by the slack of its point and t is rounded up, so
 * the certificate never accepts a member that a rounding error could have put behind. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "sweep/sweep_internal.h"

/* |a - b|, rounded up by a few ulps. */
static double distance_up(const double *a, const double *b)
{
    double d2 = 0;
    for (int c = 0; c < 3; c++)
        d2 += (a[c] - b[c]) * (a[c] - b[c]);
    return sqrt(d2) * (1 + 8 * DBL_EPSILON);
}

int fl_sweep_walk_answer(const fl_sweep *s, fl_sweep_walk *w, const double *q3, fl_closest *r)
{
    if (!w->valid || w->updates != s->updates) return 0;
    double slack = fl_sweep_query_slack(s, q3);
    double t = distance_up(q3, w->center) + slack;
    double m = INFINITY, second = INFINITY, bary[3], point[3];
    size_t best = 0, i = 0;
    for (; i < w->n; i++) {
        if (w->d[i] - w->slack - t > m) break; /* this member and the rest cannot beat m */
        double b[3], p[3];
        double d = fl_sweep_node_distance(s, s->nodes + w->leaf[i], q3, b, p);
        if (d < m) {
            second = m;
            m = d;
            best = i;
            memcpy(bary, b, sizeof bary);
            memcpy(point, p, sizeof point);
        } else if (d < second) {
            second = d;
        }
    }
    if (!(m + slack <= w->bound - t)) return 0; /* an outside region might come nearer */
    size_t measured = i;
    /* The nearest any other leaf can be: measured members, the first unmeasured one (the
     * members are sorted), the outside. For the §3.3 ball of the caller. */
    second -= slack;
    if (i < w->n && w->d[i] - w->slack - t < second) second = w->d[i] - w->slack - t;
    w->second = fmin(second, w->bound - t);
    r->distance = r->lower = r->upper = m;
    r->element = s->nodes[w->leaf[best]].element;
    w->answer = w->leaf[best];
    memcpy(r->bary, bary, sizeof bary);
    memcpy(r->point, point, sizeof point);
    r->exact = 1;
    r->reused = measured == 1; /* one distance from an earlier query's region, as §3.3 */
    r->visited = measured;
    w->answered++;
    return 1;
}

/* Adds leaf `id` at distance d: when full, the farthest of the members and it leaves and its
 * distance becomes the bound (and the search threshold). */
static void add_member(fl_sweep_walk *w, uint32_t id, double d, double *threshold)
{
    if (w->n < FL_SWEEP_WALK_CAP) {
        w->leaf[w->n] = id;
        w->d[w->n++] = d;
        return;
    }
    w->trimmed++;
    size_t far = 0;
    for (size_t i = 1; i < w->n; i++)
        if (w->d[i] > w->d[far]) far = i;
    if (d < w->d[far]) {
        double out = w->d[far];
        w->leaf[far] = id;
        w->d[far] = d;
        d = out;
    }
    if (d - w->slack < w->bound) w->bound = d - w->slack;
    if (w->bound < *threshold) *threshold = w->bound;
}

/* Members in ascending distance (insertion sort: at most FL_SWEEP_WALK_CAP of them). */
static void sort_members(fl_sweep_walk *w)
{
    for (size_t i = 1; i < w->n; i++) {
        uint32_t id = w->leaf[i];
        double d = w->d[i];
        size_t j = i;
        for (; j > 0 && w->d[j - 1] > d; j--) {
            w->leaf[j] = w->leaf[j - 1];
            w->d[j] = w->d[j - 1];
        }
        w->leaf[j] = id;
        w->d[j] = d;
    }
}

/* A region pruned with lower bound lo: the bound is the smallest of them. */
static void prune(fl_sweep_walk *w, double lo)
{
    if (lo < w->bound) w->bound = lo;
}

int fl_sweep_walk_build(const fl_sweep *s, fl_sweep_walk *w, const double *q3, double reach,
                        uint32_t seed, uint32_t *stack, fl_closest *r)
{
    double bary[3], point[3], b[3], p[3];
    w->valid = 0;
    w->n = 0;
    w->bound = INFINITY;
    w->slack = fl_sweep_query_slack(s, q3);
    w->updates = s->updates;
    memcpy(w->center, q3, sizeof w->center);
    double threshold =
        fl_sweep_node_distance(s, s->nodes + seed, q3, b, p) + 2 * reach + 2 * w->slack;
    if (!(threshold < INFINITY)) return 0;
    double best = INFINITY;
    uint32_t best_leaf = FL_SWEEP_LEAF;
    size_t top = 0, measured = 1;
    stack[top++] = 0;
    while (top > 0) {
        uint32_t id = stack[--top];
        const fl_sweep_node *node = s->nodes + id;
        if (s->box) {
            double lo2 = fl_sweep_box_dist2(s->box[id].b, q3);
            w->boxes++;
            double cut = threshold + w->slack;
            if (lo2 >= cut * cut) {
                prune(w, sqrt(lo2) - w->slack);
                continue;
            }
        }
        if (s->box && !fl_sweep_is_leaf(node)) {
            /* Within the threshold by its box: split without measuring its swept element
             * (issue #9, as query.c's searches; the children's boxes decide). */
            stack[top++] = node->child[1];
            stack[top++] = node->child[0];
            continue;
        }
        double d = fl_sweep_node_distance(s, node, q3, b, p);
        measured++;
        if (fl_sweep_is_leaf(node)) {
            if (d < best) {
                best = d;
                best_leaf = id;
                memcpy(bary, b, sizeof bary);
                memcpy(point, p, sizeof point);
            }
            if (d < threshold)
                add_member(w, id, d, &threshold);
            else
                prune(w, d - w->slack);
            continue;
        }
        double lo = d - node->eps - w->slack;
        if (lo >= threshold) {
            prune(w, lo);
            continue;
        }
        /* The nearer child on top, so that members are found early when the region is full. */
        stack[top++] = node->child[1];
        stack[top++] = node->child[0];
    }
    w->built++;
    if (best_leaf == FL_SWEEP_LEAF || w->n == 0) return 0;
    sort_members(w);
    w->valid = 1;
    w->second = w->n > 1 ? fmin(w->bound, w->d[1] - w->slack) : w->bound;
    r->distance = r->lower = r->upper = best;
    r->element = s->nodes[best_leaf].element;
    w->answer = best_leaf;
    memcpy(r->bary, bary, sizeof bary);
    memcpy(r->point, point, sizeof point);
    r->exact = 1;
    r->reused = 0;
    r->visited = measured;
    return 1;
}
