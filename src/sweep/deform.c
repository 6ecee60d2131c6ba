/* Non-rigid motion of a mesh (Guéziec §5.3): new vertex positions for the same triangles, and
 * the hierarchy updated bottom-up without rebuilding, so that queries stay exact.
 *
 * "For a smooth deformation, the motion of the mesh can be well approximated locally by a
 * rigid motion. A rigid motion does not affect the width of our bounding volumes" (§5.3).
 * So every node keeps its topology and its base triangle's shape, and moves the base triangle
 * by the rigid motion A(x) = R (x − ō) + n̄ that best fits its corners' old and new positions
 * (least squares, Horn's quaternion method; R is only a heuristic, correctness never depends
 * on it). The sphere radius ε becomes the smaller of two conservative bounds computed from the
 * children only:
 *  - inflation (§5.3, second method, with displacements measured relative to the node's own
 *    rigid motion): every old vertex p was within ε_old of the old base and A is an isometry,
 *    so the new vertex p' is within ε_old + |p' − A p| of the new base. The deviation
 *    dev = max |p' − A p| is bounded bottom-up: |p' − A p| ≤ |p' − A_c p| + |(A_c − A) p|
 *    for the child c holding p; the first term is ≤ dev(c), and the second is an affine
 *    function of p over the child's old volume (its old base swept by its old ε), so it is at
 *    most its largest value at a base corner plus ‖R_c − R‖ ε_c. A leaf measures its corners.
 *  - containment: a child's new volume lies inside the node's of radius ε_c + (largest distance
 *    of a child base corner to the node's base): the distance to a convex set is convex, so
 *    over a triangle it peaks at a corner. It does not accumulate over frames.
 * Either way every vertex of the node lies within ε of its base triangle, hence (the swept
 * volume being convex) every triangle of the node: the invariant the priority process of
 * §3.2 relies on. The cost is O(T) (a 4x4 eigenproblem and a few point-triangle distances a
 * node), against O(T log T) geometry for a build. */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "core/core.h"
#include "sweep/sweep_internal.h"

/* Per-node scratch of one update (216 bytes a node). */
typedef struct node_motion {
    double old_sum[3], new_sum[3]; /* sums of the corner positions of the node's triangles */
    double cross[9];               /* Σ old · newᵀ over the corners */
    double corners;                /* how many corners were summed */
    double r[9];                   /* the fitted rotation, row-major */
    double dev;                    /* bound on |p' − A p| over the node's vertices */
    double old_eps;
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

/* The eigenvector of the largest eigenvalue of the symmetric 4x4 matrix a (destroyed), by
 * cyclic Jacobi rotations. */
static void top_eigenvector4(double a[4][4], double *out)
{
    double v[4][4];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            v[i][j] = i == j;
    for (int sweep = 0; sweep < 32; sweep++) {
        double off = 0, diag = 0;
        for (int i = 0; i < 4; i++) {
            diag += fabs(a[i][i]);
            for (int j = i + 1; j < 4; j++)
                off += fabs(a[i][j]);
        }
        if (!(off > 1e-15 * diag)) break;
        for (int p = 0; p < 3; p++)
            for (int q = p + 1; q < 4; q++) {
                if (a[p][q] == 0) continue;
                double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                double t = (theta >= 0 ? 1 : -1) / (fabs(theta) + sqrt(theta * theta + 1));
                double c = 1 / sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 4; k++) {
                    double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 4; k++) {
                    double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 4; k++) {
                    double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    int best = 0;
    for (int i = 1; i < 4; i++)
        if (a[i][i] > a[best][best]) best = i;
    for (int k = 0; k < 4; k++)
        out[k] = v[k][best];
}

/* The rotation that best maps the node's old corners onto the new ones about their means
 * (Horn 1987: the top eigenvector of a 4x4 matrix of the cross-covariance is the quaternion).
 * Falls back to the identity if the numbers are not finite. */
static void fit_rotation(node_motion *m)
{
    double s[3][3], n = m->corners;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            s[i][j] = m->cross[3 * i + j] - m->old_sum[i] * m->new_sum[j] / n;
    double a[4][4] = {
        {s[0][0] + s[1][1] + s[2][2], s[1][2] - s[2][1], s[2][0] - s[0][2], s[0][1] - s[1][0]},
        {s[1][2] - s[2][1], s[0][0] - s[1][1] - s[2][2], s[0][1] + s[1][0], s[2][0] + s[0][2]},
        {s[2][0] - s[0][2], s[0][1] + s[1][0], -s[0][0] + s[1][1] - s[2][2], s[1][2] + s[2][1]},
        {s[0][1] - s[1][0], s[2][0] + s[0][2], s[1][2] + s[2][1], -s[0][0] - s[1][1] + s[2][2]}};
    double q[4];
    top_eigenvector4(a, q);
    double len = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(len > 0.5 && isfinite(len))) q[0] = 1, q[1] = q[2] = q[3] = 0, len = 1;
    double w = q[0] / len, x = q[1] / len, y = q[2] / len, z = q[3] / len;
    double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                   2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                   2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
    for (int i = 0; i < 9; i++)
        m->r[i] = r[i];
}

/* A(p) = R (p − ō) + n̄, the node's fitted rigid motion. */
static void apply_motion(const node_motion *m, const double *p, double *out)
{
    double d[3];
    for (int c = 0; c < 3; c++)
        d[c] = p[c] - m->old_sum[c] / m->corners;
    for (int c = 0; c < 3; c++)
        out[c] = m->r[3 * c] * d[0] + m->r[3 * c + 1] * d[1] + m->r[3 * c + 2] * d[2] +
                 m->new_sum[c] / m->corners;
}

/* A⁻¹(p) = Rᵀ (p − n̄) + ō. */
static void undo_motion(const node_motion *m, const double *p, double *out)
{
    double d[3];
    for (int c = 0; c < 3; c++)
        d[c] = p[c] - m->new_sum[c] / m->corners;
    for (int c = 0; c < 3; c++)
        out[c] = m->r[c] * d[0] + m->r[3 + c] * d[1] + m->r[6 + c] * d[2] +
                 m->old_sum[c] / m->corners;
}

static void accumulate(node_motion *m, const double *from, const double *to)
{
    for (int i = 0; i < 3; i++) {
        m->old_sum[i] += from[i];
        m->new_sum[i] += to[i];
        for (int j = 0; j < 3; j++)
            m->cross[3 * i + j] += from[i] * to[j];
    }
    m->corners += 1;
}

/* A leaf's corners, old (its stored triangle, still in place during the internal pass) and
 * new. */
static const double *leaf_new_corner(const fl_sweep *s, const fl_sweep_node *leaf,
                                     const double *xyz, int k)
{
    return xyz + 3 * (size_t)s->tri[3 * (size_t)leaf->element + k];
}

/* A leaf: accumulates its corners' motion. Returns the largest displacement. */
static double measure_leaf(const fl_sweep *s, const fl_sweep_node *node, const double *xyz,
                           node_motion *m)
{
    double largest = 0;
    *m = (node_motion){.corners = 0};
    for (int k = 0; k < 3; k++) {
        const double *to = leaf_new_corner(s, node, xyz, k);
        accumulate(m, node->v + 3 * k, to);
        largest = fmax(largest, dist3(to, node->v + 3 * k));
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

/* max |(A_c − A) p| over the child's old volume: at its old base corners (recovered from the
 * new ones by A_c⁻¹), plus ‖R_c − R‖_F times its old radius. */
static double motion_gap(const node_motion *m, const node_motion *mc, const fl_sweep_node *child)
{
    double gap = 0, rdiff = 0;
    for (int k = 0; k < 3; k++) {
        double old[3], a[3], ac[3];
        undo_motion(mc, child->v + 3 * k, old);
        apply_motion(mc, old, ac);
        apply_motion(m, old, a);
        gap = fmax(gap, dist3(a, ac));
    }
    for (int i = 0; i < 9; i++)
        rdiff += (m->r[i] - mc->r[i]) * (m->r[i] - mc->r[i]);
    return gap + sqrt(rdiff) * mc->old_eps;
}

/* A node's deviation, radius and representative terms from one child: a leaf's are measured
 * on its corners exactly; an internal child's come from its own bounds. */
static void child_terms(const fl_sweep *s, const node_motion *m, const fl_sweep_node *node,
                        const fl_sweep_node *child, const node_motion *mc, const double *xyz,
                        double *dev, double *reach, const double **rep)
{
    if (!fl_sweep_is_leaf(child)) {
        *dev = mc->dev + motion_gap(m, mc, child);
        *reach = child->eps + corner_reach(node->v, child);
        *rep = child->rep;
        return;
    }
    double worst = 0, bary[3], closest[3];
    *dev = 0;
    for (int k = 0; k < 3; k++) {
        const double *to = leaf_new_corner(s, child, xyz, k);
        double fitted[3];
        apply_motion(m, child->v + 3 * k, fitted);
        *dev = fmax(*dev, dist3(to, fitted));
        worst = fmax(worst, fl_sweep_triangle_closest(to, node->v, node->v + 3, node->v + 6, bary,
                                                      closest));
    }
    *reach = sqrt(worst);
    *rep = leaf_new_corner(s, child, xyz, 0);
}

/* Nodes with at most this many triangles measure their radius and deviation on their
 * vertices exactly instead of from the children's bounds: chaining the triangle inequality up
 * every level is loose, and near the leaves, where queries spend their time, tightness pays.
 * Each vertex is measured at about log2(EXACT_LEAVES) levels. */
#define EXACT_LEAVES 128

/* Exact deviation and radius of a small node over its vertices (leaves still hold their old
 * corners). */
static void exact_terms(const fl_sweep *s, const fl_sweep_node *node, const node_motion *m,
                        const double *xyz, double *dev, double *eps)
{
    uint32_t stack[2 * EXACT_LEAVES];
    size_t top = 0;
    double worst = 0, bary[3], closest[3];
    *dev = 0;
    stack[top++] = node->child[0];
    stack[top++] = node->child[1];
    while (top > 0) {
        const fl_sweep_node *d = s->nodes + stack[--top];
        if (!fl_sweep_is_leaf(d)) {
            stack[top++] = d->child[0];
            stack[top++] = d->child[1];
            continue;
        }
        for (int k = 0; k < 3; k++) {
            const double *to = leaf_new_corner(s, d, xyz, k);
            double fitted[3];
            apply_motion(m, d->v + 3 * k, fitted);
            *dev = fmax(*dev, dist3(to, fitted));
            worst = fmax(worst, fl_sweep_triangle_closest(to, node->v, node->v + 3, node->v + 6,
                                                          bary, closest));
        }
    }
    *eps = sqrt(worst);
}

/* An internal node, once both children are done (its leaf children still hold their old
 * corners): fit, move, bound ε both ways, pick the representative. */
static void move_internal(fl_sweep *s, fl_sweep_node *node, node_motion *all, size_t id,
                          const double *xyz)
{
    node_motion *m = all + id;
    const node_motion *ch[2] = {all + node->child[0], all + node->child[1]};
    *m = (node_motion){.corners = ch[0]->corners + ch[1]->corners, .old_eps = node->eps};
    for (int i = 0; i < 9; i++) {
        m->cross[i] = ch[0]->cross[i] + ch[1]->cross[i];
        if (i < 3) {
            m->old_sum[i] = ch[0]->old_sum[i] + ch[1]->old_sum[i];
            m->new_sum[i] = ch[0]->new_sum[i] + ch[1]->new_sum[i];
        }
    }
    fit_rotation(m);
    for (int k = 0; k < 3; k++) {
        double moved[3];
        apply_motion(m, node->v + 3 * k, moved);
        for (int c = 0; c < 3; c++)
            node->v[3 * k + c] = moved[c];
    }
    double mean[3], contained = 0, best_rep = INFINITY, exact = INFINITY;
    for (int c = 0; c < 3; c++)
        mean[c] = m->new_sum[c] / m->corners;
    if (m->corners <= 3 * EXACT_LEAVES) exact_terms(s, node, m, xyz, &m->dev, &exact);
    for (int k = 0; k < 2; k++) {
        double dev, reach;
        const double *rep;
        child_terms(s, m, node, s->nodes + node->child[k], ch[k], xyz, &dev, &reach, &rep);
        if (exact == INFINITY) m->dev = fmax(m->dev, dev);
        contained = fmax(contained, reach);
        /* The representative (an upper bound for tolerance queries, query.c) stays a vertex of
         * the node: the children's candidate nearest the node's mean. */
        double d = dist3(rep, mean);
        if (d < best_rep) {
            best_rep = d;
            for (int c = 0; c < 3; c++)
                node->rep[c] = rep[c];
        }
    }
    node->eps = fl_sweep_widen(fmin(fmin(node->eps + m->dev, contained), exact), s->scale);
}

fl_status fl_sweep_update_vertices(fl_sweep *sweep, const double *xyz, fl_error *err)
{
    if (!sweep || !xyz)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "sweep and vertices must not be NULL");
    if (!sweep->tri)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "only a mesh hierarchy (fl_sweep_build) can move its vertices");
    double scale = sweep->scale;
    size_t bad = fl_sweep_coords_scale(xyz, 3 * sweep->vertex_count, &scale);
    if (bad < 3 * sweep->vertex_count)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "vertex %zu is not finite or beyond 1e150",
                       bad / 3);
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
            largest = fmax(largest, measure_leaf(sweep, node, xyz, m + i));
        else
            move_internal(sweep, node, m, i, xyz);
    }
    for (size_t i = 0; i < sweep->node_count; i++) { /* now the leaves move */
        fl_sweep_node *node = sweep->nodes + i;
        if (!fl_sweep_is_leaf(node)) continue;
        for (int k = 0; k < 3; k++)
            for (int c = 0; c < 3; c++)
                node->v[3 * k + c] = leaf_new_corner(sweep, node, xyz, k)[c];
    }
    free(m);
    if (sweep->box) fl_sweep_compute_boxes(sweep); /* in place: the array is already there */
    /* §5.2: cursors widen their kept intervals by the largest displacement (query.c). */
    sweep->moved += fl_sweep_widen(largest, scale);
    sweep->updates++;
    return FL_OK;
}
