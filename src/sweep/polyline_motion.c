/* Non-rigid motion of a polyline (Guéziec §5.3 for the curves of §3): new point positions, and
 * the capsules of the §3.1 hierarchy updated bottom-up without rebuilding, so queries stay
 * exact. The polyline analogue of deform.c, simpler because a node's base segment is the chord
 * p_i p_j of its chain (build_polyline.c): it moves with the chain's end points, so no motion
 * needs fitting. A node's new radius is the smallest of three bounds, each valid alone:
 *  - inflation (§5.3, second method): for a point p of the chain with nearest point
 *    c = (1−λ) p_i + λ p_j on the old chord, c' = (1−λ) p_i' + λ p_j' lies on the new chord
 *    and |c' − c| ≤ max(δ_i, δ_j), so |p' − c'| ≤ δ_p + ε_old + max(δ_i, δ_j), where δ is a
 *    point's displacement: ε ≤ ε_old + δ_max(node) + max(δ_i, δ_j);
 *  - containment: a point of a child's capsule is within ε_c of the child's chord, and the
 *    distance to the new chord is convex, so it peaks at the child chord's end points: ε ≤
 *    ε_c + their largest distance to the chord (no accumulation over updates);
 *  - exact, for nodes of at most EXACT_SEGMENTS segments: the largest distance of a chain
 *    point to the chord (§3.1's own definition).
 * The capsule is convex, so containing the chain's points it contains its segments. O(n) a
 * step with the exact term near the leaves (each point measured at about log2(128) levels). */
#include <math.h>
#include <stdlib.h>

#include "core/core.h"
#include "sweep/sweep_internal.h"

#define EXACT_SEGMENTS 128

typedef struct chain_motion {
    size_t first, last; /* the chain's end points (indices into the polyline) */
    size_t segments;
    double moved; /* the largest displacement of the chain's points */
} chain_motion;

static void point_at(const fl_sweep *s, const double *points, size_t k, double *out)
{
    for (int c = 0; c < 3; c++)
        out[c] = c < s->dim ? points[(size_t)s->dim * k + c] : 0;
}

static double dist3(const double *a, const double *b)
{
    double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* Distance from p to the chord of `node` (its current v). */
static double chord_distance(const fl_sweep_node *node, const double *p)
{
    double t, c[3];
    return sqrt(fl_sweep_segment_closest(p, node->v, node->v + 3, &t, c));
}

static void set_chord(fl_sweep_node *node, const double *a, const double *b)
{
    for (int c = 0; c < 3; c++) {
        node->v[c] = a[c];
        node->v[3 + c] = node->v[6 + c] = b[c];
    }
}

/* A leaf (segment e = p_e p_{e+1 mod n}): moves it and records its motion. */
static void move_leaf(const fl_sweep *s, fl_sweep_node *node, const double *points,
                      chain_motion *m)
{
    size_t n = s->vertex_count;
    double a[3], b[3];
    m->first = node->element;
    m->last = (m->first + 1) % n;
    m->segments = 1;
    point_at(s, points, m->first, a);
    point_at(s, points, m->last, b);
    m->moved = fmax(dist3(a, node->v), dist3(b, node->v + 3));
    set_chord(node, a, b);
}

/* An internal node once both children moved: the three bounds of the file comment. */
static void move_internal(const fl_sweep *s, fl_sweep_node *node, const double *points,
                          chain_motion *all, size_t id)
{
    chain_motion *m = all + id, *c0 = all + node->child[0], *c1 = all + node->child[1];
    size_t n = s->vertex_count;
    m->first = c0->first;
    m->last = c1->last;
    m->segments = c0->segments + c1->segments;
    m->moved = fmax(c0->moved, c1->moved);
    double a[3], b[3];
    point_at(s, points, m->first, a);
    point_at(s, points, m->last, b);
    double inflated = node->eps + m->moved + fmax(dist3(a, node->v), dist3(b, node->v + 3));
    set_chord(node, a, b);
    double contained = 0;
    for (int k = 0; k < 2; k++) {
        const fl_sweep_node *child = s->nodes + node->child[k];
        contained = fmax(contained, child->eps + fmax(chord_distance(node, child->v),
                                                      chord_distance(node, child->v + 3)));
    }
    double exact = INFINITY;
    if (m->segments <= EXACT_SEGMENTS) {
        exact = 0;
        for (size_t j = 1; j < m->segments; j++) {
            double p[3];
            point_at(s, points, (m->first + j) % n, p);
            exact = fmax(exact, chord_distance(node, p));
        }
    }
    node->eps = fl_sweep_widen(fmin(fmin(inflated, contained), exact), s->scale);
}

fl_status fl_sweep_polyline_update(fl_sweep *sweep, const double *points, fl_error *err)
{
    if (!sweep || !points)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "sweep and points must not be NULL");
    if (sweep->triangles)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "only a polyline hierarchy (fl_sweep_polyline_build) takes new points; "
                       "use fl_sweep_update_vertices for a mesh");
    size_t count = sweep->vertex_count * (size_t)sweep->dim;
    double scale = sweep->scale;
    size_t bad = fl_sweep_coords_scale(points, count, &scale);
    if (bad < count)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "polyline point %zu is not finite or beyond 1e150",
                       bad / (size_t)sweep->dim);
    chain_motion *m = fl_alloc_array(sweep->node_count, sizeof *m);
    if (!m) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for a polyline update");
    sweep->scale = scale; /* only grows the rounding slack */
    double largest = 0;
    /* Children are numbered after their parent (build_polyline.c): a reverse pass is
     * bottom-up. */
    for (size_t i = sweep->node_count; i-- > 0;) {
        fl_sweep_node *node = sweep->nodes + i;
        if (fl_sweep_is_leaf(node)) {
            move_leaf(sweep, node, points, m + i);
            largest = fmax(largest, m[i].moved);
        } else {
            move_internal(sweep, node, points, m, i);
        }
    }
    free(m);
    if (sweep->box) fl_sweep_compute_boxes(sweep);
    /* §5.2: cursors widen their kept intervals by the largest displacement (query.c). */
    sweep->moved += fl_sweep_widen(largest, scale);
    sweep->updates++;
    return FL_OK;
}
