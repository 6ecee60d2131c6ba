/* Non-rigid motion of a mesh (Guéziec §5.3): new vertex positions for the same triangles, and
 * the hierarchy updated bottom-up without rebuilding, so that queries stay exact.
 *
 * Every node keeps its topology (its triangles never change) and its base triangle's shape;
 * the base triangle is translated by the node's mean displacement τ (a smooth deformation is
 * locally close to a rigid motion, §5.3, and its translation part costs nothing), and the
 * sphere radius ε becomes the smaller of two conservative bounds, both computed from the
 * children only:
 *  - inflation (§5.3, second method): every vertex was within ε_old of the old base, and moved
 *    by Δp; relative to the translated base it moved by |Δp − τ| ≤ dev, where
 *    dev(node) = max over children c of dev(c) + |τ_c − τ| (triangle inequality; a leaf
 *    measures its three corners). So ε_old + dev bounds the new vertices.
 *  - containment: a child's volume (its base triangle swept by ε_c) lies inside the node's
 *    volume of radius ε_c + (largest distance of a child base corner to the node's base):
 *    the distance to a convex set is convex, so over a triangle it peaks at a corner. For
 *    leaf children this is the exact distance of the triangle's vertices. Unlike inflation,
 *    it does not accumulate over frames.
 * Either way every vertex of the node lies within ε of its base triangle, hence (the swept
 * volume being convex) every triangle of the node: the invariant the priority process of
 * §3.2 relies on. The cost is O(T) (six point-triangle distances a node), against
 * O(T log T) geometry for a build. */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "core/core.h"
#include "sweep/sweep_internal.h"

/* Per-node scratch of one update. */
typedef struct node_motion {
    double old_sum[3], new_sum[3]; /* sums of the corner positions of the node's triangles */
    double corners;                /* how many corners were summed */
    double tau[3];                 /* mean displacement */
    double dev;                    /* bound on |Δp − τ| over the node's vertices */
} node_motion;

static double norm3(const double *a)
{
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

static double dist3(const double *a, const double *b)
{
    double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return norm3(d);
}

/* A leaf: measures its corners' displacements, then moves them. Returns the largest. */
static double move_leaf(fl_sweep *s, fl_sweep_node *node, const double *xyz, node_motion *m)
{
    const uint32_t *t = s->tri + 3 * (size_t)node->element;
    double disp[3][3], largest = 0;
    for (int c = 0; c < 3; c++)
        m->old_sum[c] = m->new_sum[c] = 0;
    for (int k = 0; k < 3; k++)
        for (int c = 0; c < 3; c++) {
            double to = xyz[3 * (size_t)t[k] + c];
            disp[k][c] = to - node->v[3 * k + c];
            m->old_sum[c] += node->v[3 * k + c];
            m->new_sum[c] += to;
        }
    m->corners = 3;
    for (int c = 0; c < 3; c++)
        m->tau[c] = (m->new_sum[c] - m->old_sum[c]) / 3;
    m->dev = 0;
    for (int k = 0; k < 3; k++) {
        double rel[3] = {disp[k][0] - m->tau[0], disp[k][1] - m->tau[1], disp[k][2] - m->tau[2]};
        m->dev = fmax(m->dev, norm3(rel));
        largest = fmax(largest, norm3(disp[k]));
        for (int c = 0; c < 3; c++)
            node->v[3 * k + c] = xyz[3 * (size_t)t[k] + c];
    }
    return largest;
}

/* The largest distance from a corner of `child`'s base triangle to the triangle `base`. */
static double corner_reach(const double *base, const fl_sweep_node *child)
{
    double worst = 0, bary[3], closest[3];
    for (int k = 0; k < 3; k++)
        worst = fmax(worst, fl_sweep_triangle_closest(child->v + 3 * k, base, base + 3, base + 6,
                                                      bary, closest));
    return sqrt(worst);
}

/* An internal node, once both children are done: translate, bound ε both ways, pick rep. */
static void move_internal(fl_sweep *s, fl_sweep_node *node, node_motion *all, size_t id)
{
    node_motion *m = all + id;
    const node_motion *ch[2] = {all + node->child[0], all + node->child[1]};
    for (int c = 0; c < 3; c++) {
        m->old_sum[c] = ch[0]->old_sum[c] + ch[1]->old_sum[c];
        m->new_sum[c] = ch[0]->new_sum[c] + ch[1]->new_sum[c];
    }
    m->corners = ch[0]->corners + ch[1]->corners;
    double mean[3];
    for (int c = 0; c < 3; c++) {
        m->tau[c] = (m->new_sum[c] - m->old_sum[c]) / m->corners;
        mean[c] = m->new_sum[c] / m->corners;
    }
    m->dev = 0;
    for (int k = 0; k < 2; k++) {
        double rel[3] = {ch[k]->tau[0] - m->tau[0], ch[k]->tau[1] - m->tau[1],
                         ch[k]->tau[2] - m->tau[2]};
        m->dev = fmax(m->dev, ch[k]->dev + norm3(rel));
    }
    for (int k = 0; k < 3; k++)
        for (int c = 0; c < 3; c++)
            node->v[3 * k + c] += m->tau[c];
    double inflated = node->eps + m->dev, contained = 0, best_rep = INFINITY;
    for (int k = 0; k < 2; k++) {
        const fl_sweep_node *child = s->nodes + node->child[k];
        contained = fmax(contained, child->eps + corner_reach(node->v, child));
        /* The representative (an upper bound for tolerance queries, query.c) stays a vertex of
         * the node: a leaf's first corner or a child's representative, the one nearest the
         * node's mean. */
        const double *r = fl_sweep_is_leaf(child) ? child->v : child->rep;
        double d = dist3(r, mean);
        if (d < best_rep) {
            best_rep = d;
            for (int c = 0; c < 3; c++)
                node->rep[c] = r[c];
        }
    }
    node->eps = fl_sweep_widen(fmin(inflated, contained), s->scale);
}

fl_status fl_sweep_update_vertices(fl_sweep *sweep, const double *xyz, fl_error *err)
{
    if (!sweep || !xyz)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "sweep and vertices must not be NULL");
    if (!sweep->tri)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "only a mesh hierarchy (fl_sweep_build) can move its vertices");
    double scale = sweep->scale;
    for (size_t i = 0; i < 3 * sweep->vertex_count; i++) {
        if (!fl_sweep_coord_ok(xyz[i]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "vertex %zu is not finite or beyond 1e150", i / 3);
        scale = fmax(scale, fabs(xyz[i]));
    }
    node_motion *m = fl_alloc_array(sweep->node_count, sizeof *m);
    if (!m) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for a hierarchy update");
    /* The coordinates only grow the rounding slack: keep the larger scale. */
    sweep->scale = scale;
    double largest = 0;
    /* Children are created after their parent (build_mesh.c), so a reverse pass over the
     * node array is bottom-up. */
    for (size_t i = sweep->node_count; i-- > 0;) {
        fl_sweep_node *node = sweep->nodes + i;
        if (fl_sweep_is_leaf(node))
            largest = fmax(largest, move_leaf(sweep, node, xyz, m + i));
        else
            move_internal(sweep, node, m, i);
    }
    free(m);
    /* §5.2: cursors widen their kept intervals by the largest displacement (query.c). */
    sweep->moved += fl_sweep_widen(largest, scale);
    sweep->updates++;
    return FL_OK;
}
