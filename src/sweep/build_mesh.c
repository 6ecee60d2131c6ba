/* The mesh hierarchy: a binary tree over the triangles whose bounding volumes are triangles
 * swept by spheres, the volume type of §4.1. Simplification (documented in docs/sweep.md):
 * Guéziec obtains the hierarchy from error-bounded edge collapses and refines it by vertex
 * splits (§4.2); here it is built top-down by median splits of the triangle centroids, and
 * each internal node gets its own bounding triangle: a triangle in the principal plane of the
 * node's vertices enclosing their projection, with ε = the largest distance of a vertex to it.
 * The swept volume is convex, so containing the vertices it contains their triangles, and the
 * priority process of §3.2 runs on it unchanged.
 *
 * Two passes (issue #9, build time against CGAL's AABB tree): the median splits need only the
 * centroids, so they run first, top-down on 32-byte records, numbering the leaves last in
 * split order; then the elements are fitted bottom-up (reverse creation order), each node
 * reading its triangles from its contiguous run of leaves. Bottom-up, a large node finds ε by
 * branch and bound over its finished subtree (max_distance_below) instead of measuring every
 * vertex at every level; the result is the same largest vertex distance. */
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE /* madvise */
#endif
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "core/core.h"
#include "sweep/sweep_internal.h"

typedef struct range {
    size_t start, end; /* triangles split[start..end) */
    uint32_t node;
} range;

/* A triangle during the median splits: its centroid and index (32 bytes, so the splits move
 * little memory). */
typedef struct split_rec {
    double centroid[3];
    uint32_t id;
} split_rec;

/* Eigenvectors (columns of vec) of the symmetric 3x3 matrix a by cyclic Jacobi rotations;
 * the eigenvalues are left on a's diagonal. */
static void jacobi3(double a[3][3], double vec[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            vec[i][j] = i == j;
    for (int sweep = 0; sweep < 32; sweep++) {
        double off = fabs(a[0][1]) + fabs(a[0][2]) + fabs(a[1][2]);
        double diag = fabs(a[0][0]) + fabs(a[1][1]) + fabs(a[2][2]);
        if (!(off > 1e-15 * diag)) return;
        for (int p = 0; p < 2; p++)
            for (int q = p + 1; q < 3; q++) {
                if (a[p][q] == 0) continue;
                double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                double t = (theta >= 0 ? 1 : -1) / (fabs(theta) + sqrt(theta * theta + 1));
                double c = 1 / sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 3; k++) { /* a = a J */
                    double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; k++) { /* a = J^T a */
                    double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; k++) {
                    double vkp = vec[k][p], vkq = vec[k][q];
                    vec[k][p] = c * vkp - s * vkq;
                    vec[k][q] = s * vkp + c * vkq;
                }
            }
    }
}

/* A frame for a node of a few triangles without the eigen-solve: the normal e[2] is their
 * summed (area-weighted) normal, and e[0] the direction of largest spread of the points in
 * that plane, in closed form from the covariance cov projected to the plane (the 2x2
 * eigenvector at angle atan2(2 b, a - c) / 2). Near the leaves the Jacobi fit's fixed cost per
 * node dominated the build (issue #9); the frame only shapes the element, whose ε is measured
 * afterwards, so any frame is correct. Returns 0 when the triangles are too degenerate or
 * large for it; the caller then fits the principal frame. */
static int normal_frame(const fl_sweep_node *rec, size_t start, size_t end, double cov[3][3],
                        double e[3][3])
{
    double nrm[3] = {0, 0, 0};
    for (size_t i = start; i < end; i++) {
        const double *c = rec[i].v;
        double a[3] = {c[3] - c[0], c[4] - c[1], c[5] - c[2]};
        double b[3] = {c[6] - c[0], c[7] - c[1], c[8] - c[2]};
        nrm[0] += a[1] * b[2] - a[2] * b[1];
        nrm[1] += a[2] * b[0] - a[0] * b[2];
        nrm[2] += a[0] * b[1] - a[1] * b[0];
    }
    double len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (!(len > 0) || !isfinite(len)) return 0;
    for (int k = 0; k < 3; k++)
        e[2][k] = nrm[k] / len;
    /* u: the unit vector orthogonal to the normal along the axis where the normal is smallest
     * (so the cross product is well conditioned), w = n x u. */
    int ax = fabs(e[2][0]) < fabs(e[2][1]) ? 0 : 1;
    ax = fabs(e[2][2]) < fabs(e[2][ax]) ? 2 : ax;
    double u[3] = {0, 0, 0}, w[3], h = e[2][ax], u2 = 0;
    for (int k = 0; k < 3; k++) {
        u[k] = (k == ax) - h * e[2][k];
        u2 += u[k] * u[k];
    }
    if (!(u2 > 0.5)) return 0; /* |h| <= 1/sqrt(3), so u2 >= 2/3 unless rounding went wrong */
    double inv = 1 / sqrt(u2), cu[3], cw[3], a = 0, b = 0, c = 0;
    for (int k = 0; k < 3; k++)
        u[k] *= inv;
    w[0] = e[2][1] * u[2] - e[2][2] * u[1];
    w[1] = e[2][2] * u[0] - e[2][0] * u[2];
    w[2] = e[2][0] * u[1] - e[2][1] * u[0];
    for (int r = 0; r < 3; r++) {
        cu[r] = cov[r][0] * u[0] + cov[r][1] * u[1] + cov[r][2] * u[2];
        cw[r] = cov[r][0] * w[0] + cov[r][1] * w[1] + cov[r][2] * w[2];
    }
    for (int k = 0; k < 3; k++) {
        a += u[k] * cu[k];
        b += u[k] * cw[k];
        c += w[k] * cw[k];
    }
    double theta = 0.5 * atan2(2 * b, a - c);
    if (!isfinite(theta)) return 0;
    double ct = cos(theta), st = sin(theta);
    for (int k = 0; k < 3; k++) {
        e[0][k] = ct * u[k] + st * w[k];
        e[1][k] = ct * w[k] - st * u[k];
    }
    return 1;
}

/* Nodes of at most this many triangles take normal_frame instead of the Jacobi fit. Distances
 * a query computed on the npm bunny's bench streams (first 30 000 queries, random / near /
 * walk): 3: 61.60 / 26.00 / 8.47, 8: 61.67 / 26.03 / 8.44, 24: 61.73 / 26.06 / 8.45, 64:
 * 62.01 / 26.10 / 8.48; 24 removes most Jacobi calls (15 % of the build) for +0.2 %. */
#define FL_SWEEP_NORMAL_FRAME 24

/* Gathers the corners of every stride-th triangle of rec[start..end) into pts (9 doubles a
 * triangle, so the passes below stream through memory) and returns the principal frame of
 * these points (their count is returned): mean
 * and axes e[0], e[1] (largest spread first) and the normal e[2]. One pass: moments about the
 * first point (shifted, so that a mesh far from the origin does not cancel the covariance);
 * the frame only shapes the element, whose radius is measured afterwards. */
static size_t gather_frame(const fl_sweep_node *rec, size_t start, size_t end, size_t stride,
                           double *pts, double *mean, double e[3][3])
{
    const double *ref = rec[start].v;
    double sum[3] = {0, 0, 0}, s2[6] = {0, 0, 0, 0, 0, 0};
    size_t n = 0;
    for (size_t i = start; i < end; i += stride) {
        const double *t = rec[i].v;
        for (int k = 0; k < 3; k++, n++) {
            double x = t[3 * k] - ref[0], y = t[3 * k + 1] - ref[1], z = t[3 * k + 2] - ref[2];
            pts[3 * n] = t[3 * k], pts[3 * n + 1] = t[3 * k + 1], pts[3 * n + 2] = t[3 * k + 2];
            sum[0] += x, sum[1] += y, sum[2] += z;
            s2[0] += x * x, s2[1] += x * y, s2[2] += x * z;
            s2[3] += y * y, s2[4] += y * z, s2[5] += z * z;
        }
    }
    double inv = 1 / (double)n, cov[3][3];
    static const int idx[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    for (int r = 0; r < 3; r++) {
        mean[r] = ref[r] + sum[r] * inv;
        for (int c = 0; c < 3; c++)
            cov[r][c] = s2[idx[r][c]] - sum[r] * sum[c] * inv;
    }
    if (end - start <= FL_SWEEP_NORMAL_FRAME && normal_frame(rec, start, end, cov, e)) return n;
    double vec[3][3];
    jacobi3(cov, vec);
    int order[3] = {0, 1, 2};
    for (int i = 0; i < 3; i++) /* sort eigenvalues decreasing */
        for (int j = i + 1; j < 3; j++)
            if (cov[order[j]][order[j]] > cov[order[i]][order[i]]) {
                int tmp = order[i];
                order[i] = order[j];
                order[j] = tmp;
            }
    for (int i = 0; i < 3; i++)
        for (int c = 0; c < 3; c++)
            e[i][c] = vec[c][order[i]];
    return n;
}

/* A triangle enclosing the 2D points uv[0..n): over the four sides of their bounding box as
 * base and three side slopes around the one that gives area 2wh for a rectangle, the
 * smallest of the triangles whose two sides touch the points. Writes the corners to tri.
 * All twelve candidates are measured in one pass over the points (this runs once a node, on
 * every vertex below it, so it is a large part of the build). Without all_slopes only the
 * four with the rectangle's slope are tried: nodes of at most FL_SWEEP_EXACT triangles take
 * that (a third of the cost; on the npm bunny the first 30 000 queries of the bench streams
 * computed 61.85 / 26.08 / 8.44 distances instead of 61.73 / 26.06 / 8.45). */
static void enclosing_triangle(const double *uv, size_t n, const double *lo, const double *hi,
                               int all_slopes, double tri[3][2])
{
    static const int axis[4][2] = {{0, 1}, {0, 1}, {1, 0}, {1, 0}}; /* (x, y) from (u, v) */
    static const double flip[4] = {1, -1, 1, -1};
    static const double factor[3] = {0.5, 1, 2};
    double y0[4], slope[4][3], inv[4][3], left[4][3], right[4][3];
    int k0 = all_slopes ? 0 : 1, k1 = all_slopes ? 3 : 2;
    for (int o = 0; o < 4; o++) {
        int ax = axis[o][0], ay = axis[o][1];
        double w = hi[ax] - lo[ax], h = hi[ay] - lo[ay];
        double s0 = w > 0 && h > 0 ? 2 * h / w : 1;
        y0[o] = flip[o] > 0 ? lo[ay] : -hi[ay];
        for (int k = 0; k < 3; k++) {
            slope[o][k] = s0 * factor[k];
            inv[o][k] = 1 / slope[o][k];
            left[o][k] = INFINITY;
            right[o][k] = -INFINITY;
        }
    }
    for (size_t i = 0; i < n; i++) {
        for (int o = 0; o < 4; o++) {
            double x = uv[2 * i + axis[o][0]], y = flip[o] * uv[2 * i + axis[o][1]] - y0[o];
            for (int k = k0; k < k1; k++) {
                double t = y * inv[o][k], l = x - t, r = x + t;
                left[o][k] = l < left[o][k] ? l : left[o][k];
                right[o][k] = r > right[o][k] ? r : right[o][k];
            }
        }
    }
    double best = INFINITY;
    for (int o = 0; o < 4; o++)
        for (int k = k0; k < k1; k++) {
            double width = right[o][k] - left[o][k], area = slope[o][k] * width * width;
            if (!(area < best)) continue;
            best = area;
            int ax = axis[o][0], ay = axis[o][1];
            double corner[3][2] = {{left[o][k], 0},
                                   {right[o][k], 0},
                                   {(left[o][k] + right[o][k]) / 2, slope[o][k] * width / 2}};
            for (int c = 0; c < 3; c++) {
                tri[c][ax] = corner[c][0];
                tri[c][ay] = flip[o] * (corner[c][1] + y0[o]);
            }
        }
    if (best < INFINITY) return;
    /* Every candidate overflowed or was NaN: a spread so thin in one direction that 2h/w is
     * infinite or zero (found by fuzz_sweep: widths 1e-291 against 8, which left the triangle
     * unset). The 45-degree triangle on the box encloses it with finite corners. */
    double w = hi[0] - lo[0], h = hi[1] - lo[1];
    tri[0][0] = lo[0] - h;
    tri[0][1] = lo[1];
    tri[1][0] = hi[0] + h;
    tri[1][1] = lo[1];
    tri[2][0] = lo[0] + w / 2;
    tri[2][1] = lo[1] + h + w / 2;
}

/* An upper bound on the squared distance from p to the triangle v[0..8] that is exact (up to
 * rounding) when p projects into the triangle or near it, as every vertex of a node does onto
 * the node's enclosing triangle: the distance to the point of the triangle with p's
 * barycentrics, clamped to the triangle. Any point of the triangle bounds the distance from
 * above, however the barycentrics were rounded (a thin triangle cannot make it too small, as
 * the plane distance could), and ε only needs an upper bound. Points farther outside (a child's
 * corners against its parent's triangle) go through the full closest-point routine, which the
 * clamping would overestimate. */
typedef struct tri_frame {
    double a[3], b[3], d00, d01, d11, inv_denom;
    int ok;
} tri_frame;

static void tri_frame_init(tri_frame *f, const double *v)
{
    f->d00 = f->d01 = f->d11 = 0;
    for (int c = 0; c < 3; c++) {
        f->a[c] = v[3 + c] - v[c];
        f->b[c] = v[6 + c] - v[c];
        f->d00 += f->a[c] * f->a[c];
        f->d01 += f->a[c] * f->b[c];
        f->d11 += f->b[c] * f->b[c];
    }
    /* denom = |a x b|^2 = d00 d11 sin^2 of the angle at v[0]: slivers (sin below 1e-4) leave
     * the barycentrics to rounding noise and go through the full routine. */
    double denom = f->d00 * f->d11 - f->d01 * f->d01;
    f->ok = denom > 1e-8 * (f->d00 * f->d11) && isfinite(1 / denom);
    if (f->ok) f->inv_denom = 1 / denom;
}

static double tri_dist2(const tri_frame *f, const double *v, const double *p)
{
    if (f->ok) {
        double w[3] = {p[0] - v[0], p[1] - v[1], p[2] - v[2]};
        double d20 = w[0] * f->a[0] + w[1] * f->a[1] + w[2] * f->a[2];
        double d21 = w[0] * f->b[0] + w[1] * f->b[1] + w[2] * f->b[2];
        double beta = (f->d11 * d20 - f->d01 * d21) * f->inv_denom;
        double gamma = (f->d00 * d21 - f->d01 * d20) * f->inv_denom;
        if (beta > -1e-6 && gamma > -1e-6 && 1 - beta - gamma > -1e-6) {
            beta = beta > 0 ? beta : 0;
            gamma = gamma > 0 ? gamma : 0;
            double sum = beta + gamma;
            if (sum > 1) beta /= sum, gamma /= sum;
            double d2 = 0;
            for (int c = 0; c < 3; c++) {
                double x = w[c] - beta * f->a[c] - gamma * f->b[c];
                d2 += x * x;
            }
            return d2;
        }
    }
    double bary[3], closest[3];
    return fl_sweep_triangle_closest(p, v, v + 3, v + 6, bary, closest);
}

/* Triangles of a node that shape its bounding triangle (below). */
#define FL_SWEEP_SAMPLE 128

/* Nodes of at most this many triangles measure ε on every vertex, in one streaming pass over
 * their contiguous run of leaves; larger ones find it by branch and bound over their finished
 * subtree (max_distance_below), which opens a small part of it. 16 and 32 were slower (the
 * search's overhead exceeds the streamed distances it saves), 128 no faster (bunny00, CPU). */
#define FL_SWEEP_EXACT 64

/* The shape of a node's bounding element: a triangle in the principal plane of the node's
 * vertices (at the mid-plane of their spread along the normal) enclosing their projections.
 * Large nodes shape it on a sample of at most FL_SWEEP_SAMPLE of their triangles (every k-th
 * in the median-split order, so spread over the node): ε is measured or bounded over every
 * vertex afterwards, so the element contains the node whatever the sample; a vertex the
 * sample misses only widens ε. Also rep, the sampled vertex nearest to the sample's mean: a
 * point of the shape inside the element, whose distance bounds the distance to the node's
 * triangles from above (query.c). pts and uv are scratch room for 9 and 6 doubles a sampled
 * triangle. */
static void shape_triangle(const fl_sweep_node *rec, size_t start, size_t end, double *pts,
                           double *uv, fl_sweep_node *node)
{
    double mean[3], e[3][3], lo[3] = {INFINITY, INFINITY, INFINITY};
    double hi[3] = {-INFINITY, -INFINITY, -INFINITY}, best = INFINITY;
    size_t stride = (end - start + FL_SWEEP_SAMPLE - 1) / FL_SWEEP_SAMPLE;
    size_t n = gather_frame(rec, start, end, stride, pts, mean, e);
    for (size_t i = 0; i < n; i++) {
        const double *p = pts + 3 * i;
        double r2 = 0;
        for (int a = 0; a < 3; a++) {
            double x = (p[0] - mean[0]) * e[a][0] + (p[1] - mean[1]) * e[a][1] +
                       (p[2] - mean[2]) * e[a][2];
            if (a < 2) uv[2 * i + a] = x;
            lo[a] = x < lo[a] ? x : lo[a]; /* not fmin/fmax: libm calls, and x is finite */
            hi[a] = x > hi[a] ? x : hi[a];
            r2 += (p[a] - mean[a]) * (p[a] - mean[a]);
        }
        if (r2 < best) {
            best = r2;
            node->rep[0] = p[0], node->rep[1] = p[1], node->rep[2] = p[2];
        }
    }
    if (!(best < INFINITY)) memcpy(node->rep, pts, 3 * sizeof *pts); /* NaN spreads: any vertex */
    double corner[3][2], mid_n = (lo[2] + hi[2]) / 2;
    enclosing_triangle(uv, n, lo, hi, end - start > FL_SWEEP_EXACT, corner);
    for (int k = 0; k < 3; k++)
        for (int c = 0; c < 3; c++)
            node->v[3 * k + c] =
                mean[c] + corner[k][0] * e[0][c] + corner[k][1] * e[1][c] + mid_n * e[2][c];
}

/* The largest distance from a vertex of rec[start..end) to the triangle v (frame f). */
static double max_distance_exact(const tri_frame *f, const double *v, const fl_sweep_node *rec,
                                 size_t start, size_t end)
{
    double eps2 = 0;
    for (size_t i = start; i < end; i++)
        for (int k = 0; k < 3; k++) {
            double d2 = tri_dist2(f, v, rec[i].v + 3 * k);
            eps2 = d2 > eps2 ? d2 : eps2; /* a NaN is never picked */
        }
    return sqrt(eps2);
}

/* A subtree waiting in max_distance_below, with an upper bound on its vertices' distances. */
typedef struct bound_entry {
    uint32_t node;
    double ub;
} bound_entry;

/* The state of one max_distance_below. */
typedef struct bound_search {
    const fl_sweep *s;
    const tri_frame *f;
    const double *v; /* the node's triangle */
    double vscale;   /* largest |coordinate| of the node's triangle and the input */
    double found;    /* the largest distance of a vertex measured so far */
    double pruned;   /* the largest bound of a subtree left out */
    bound_entry *stack;
    size_t top;
} bound_search;

/* An upper bound on the distance from any point of child c's volume to the triangle v: every
 * such point is within ε_c of c's triangle, whose points are within the largest corner
 * distance of v (distance to a convex set is convex, so over a triangle it peaks at a corner);
 * the triangle inequality adds the two. The corner distance is widened by its rounding
 * error (64 ulps of the largest coordinate involved); ε_c is already widened. */
static double child_bound(const bound_search *b, const fl_sweep_node *c)
{
    double d2 = 0, m = b->vscale;
    for (int k = 0; k < 3; k++) {
        double x = tri_dist2(b->f, b->v, c->v + 3 * k);
        d2 = x > d2 ? x : d2;
    }
    for (int i = 0; i < 9; i++)
        m = fabs(c->v[i]) > m ? fabs(c->v[i]) : m;
    return fl_sweep_widen(sqrt(d2), m) + c->eps;
}

/* Settles the children of `id`: a leaf child's three vertices are measured; an internal
 * child is pushed with its bound unless that bound is already covered by `found`, in which
 * case it only raises `pruned`. The child with the larger bound is pushed last, so that the
 * search goes after the farthest vertices first and `found` grows early. */
static void expand(bound_search *b, uint32_t id)
{
    const fl_sweep_node *node = b->s->nodes + id;
    bound_entry e[2];
    int pushed = 0;
    for (int k = 0; k < 2; k++) {
        const fl_sweep_node *c = b->s->nodes + node->child[k];
        if (fl_sweep_is_leaf(c)) {
            for (int j = 0; j < 3; j++) {
                double d = sqrt(tri_dist2(b->f, b->v, c->v + 3 * j));
                b->found = d > b->found ? d : b->found;
            }
            continue;
        }
        double ub = child_bound(b, c);
        if (ub <= b->found) {
            b->pruned = ub > b->pruned ? ub : b->pruned;
            continue;
        }
        e[pushed++] = (bound_entry){node->child[k], ub}; /* NaN bounds too: searched below */
    }
    if (pushed == 2 && e[0].ub > e[1].ub) {
        bound_entry t = e[0];
        e[0] = e[1];
        e[1] = t;
    }
    for (int k = 0; k < pushed; k++)
        b->stack[b->top++] = e[k];
}

/* The radius of an internal node whose descendants are finished (bottom-up order): by branch
 * and bound over its subtree, the largest of (a) the distances of the vertices it measures and
 * (b) the bounds of the subtrees it leaves out because (a) already covers them. Every vertex
 * below is in a measured leaf or a left-out subtree, so the result bounds them all; it equals
 * the exact largest vertex distance up to the slack of the left-out bounds, which can only
 * exceed it when they are larger than every measured distance (they never are: a subtree is
 * left out only when its bound is at most `found`). The children's representatives are
 * vertices of the node, so their distances start `found`. `stack` holds node_count entries
 * (a depth-first search keeps at most depth + 1). */
static double max_distance_below(const fl_sweep *s, uint32_t id, const tri_frame *f,
                                 bound_entry *stack)
{
    const fl_sweep_node *node = s->nodes + id;
    bound_search b = {s, f, node->v, s->scale, 0, 0, stack, 0};
    for (int i = 0; i < 9; i++)
        b.vscale = fabs(node->v[i]) > b.vscale ? fabs(node->v[i]) : b.vscale;
    for (int k = 0; k < 2; k++) {
        const fl_sweep_node *c = s->nodes + node->child[k];
        if (fl_sweep_is_leaf(c)) continue; /* measured by expand; leaves have no rep */
        double d = sqrt(tri_dist2(f, node->v, c->rep));
        b.found = d > b.found ? d : b.found;
    }
    expand(&b, id);
    while (b.top > 0) {
        bound_entry e = b.stack[--b.top];
        if (e.ub <= b.found) {
            b.pruned = e.ub > b.pruned ? e.ub : b.pruned;
            continue;
        }
        expand(&b, e.node);
    }
    return b.found > b.pruned ? b.found : b.pruned;
}

/* Fits internal node `id` over rec[start..end) once its descendants are finished. */
static void fit_node(fl_sweep *s, uint32_t id, const fl_sweep_node *rec, size_t start, size_t end,
                     double *pts, double *uv, bound_entry *stack)
{
    fl_sweep_node *node = s->nodes + id;
    shape_triangle(rec, start, end, pts, uv, node);
    /* Measured against the stored triangle, not derived from the frame, so rounding in the
     * frame cannot shrink it. */
    tri_frame f;
    tri_frame_init(&f, node->v);
    double eps = end - start <= FL_SWEEP_EXACT ? max_distance_exact(&f, node->v, rec, start, end)
                                               : max_distance_below(s, id, &f, stack);
    node->eps = fl_sweep_widen(eps, s->scale);
}

/* Reorders split[start..end) so that split[mid] has the median centroid coordinate `axis` and
 * smaller ones precede it (Hoare quickselect). */
static void select_median(split_rec *rec, int axis, size_t start, size_t mid, size_t end)
{
    size_t lo = start, hi = end - 1;
    while (lo < hi) {
        double pivot = rec[lo + (hi - lo) / 2].centroid[axis];
        size_t i = lo, j = hi;
        while (i <= j) {
            while (rec[i].centroid[axis] < pivot)
                i++;
            while (rec[j].centroid[axis] > pivot)
                j--;
            if (i <= j) {
                split_rec tmp = rec[i];
                rec[i] = rec[j];
                rec[j] = tmp;
                i++;
                if (j == 0) break;
                j--;
            }
        }
        if (mid <= j)
            hi = j;
        else if (mid >= i)
            lo = i;
        else
            return;
    }
}

static int widest_axis(const split_rec *rec, size_t start, size_t end)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = start; i < end; i++)
        for (int c = 0; c < 3; c++) {
            double x = rec[i].centroid[c];
            lo[c] = x < lo[c] ? x : lo[c];
            hi[c] = x > hi[c] ? x : hi[c];
        }
    int axis = 0;
    for (int c = 1; c < 3; c++)
        if (hi[c] - lo[c] > hi[axis] - lo[axis]) axis = c;
    return axis;
}

static void set_leaf(const fl_mesh *m, uint32_t t, fl_sweep_node *node)
{
    for (int k = 0; k < 3; k++)
        memcpy(node->v + 3 * k, m->xyz + 3 * (size_t)m->tri[3 * (size_t)t + k],
               3 * sizeof *node->v);
    node->eps = 0;
    node->child[0] = node->child[1] = FL_SWEEP_LEAF;
    node->element = t;
}

static fl_status check_mesh(const fl_mesh *m, fl_error *err)
{
    if (!m || (m->triangle_count > 0 && !m->tri) || (m->vertex_count > 0 && !m->xyz))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "mesh or its arrays are NULL");
    if (m->triangle_count == 0)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "the mesh has no triangles");
    if (m->triangle_count >= (size_t)1 << 31)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "too many triangles (%zu)", m->triangle_count);
    for (size_t v = 0; v < m->vertex_count; v++)
        for (int c = 0; c < 3; c++)
            if (!fl_sweep_coord_ok(m->xyz[3 * v + c]))
                return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                               "vertex %zu is not finite or beyond 1e150", v);
    for (size_t t = 0; t < m->triangle_count; t++)
        for (int k = 0; k < 3; k++)
            if (m->tri[3 * t + k] >= m->vertex_count)
                return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                               "triangle %zu refers to vertex %u, but there are %zu vertices", t,
                               m->tri[3 * t + k], m->vertex_count);
    return FL_OK;
}

/* Splits triangle ranges top-down (centroids only), numbering internal nodes in creation
 * order from the root (0 .. n-2) and the leaves after them in split order (leaf of
 * split[i] = n - 1 + i), so that children come after their parents (the bottom-up passes need
 * it: here, boxes.c, deform.c) and every node's leaves are contiguous in the node array.
 * span[2 id], span[2 id + 1] keep internal node id's range of positions. */
static fl_status split_ranges(fl_sweep *s, const fl_mesh *mesh, split_rec *split, uint32_t *span,
                              const fl_sweep_options *opt, fl_error *err)
{
    size_t n = s->elements, top = 0, next = 1;
    if (n == 1) {
        set_leaf(mesh, split[0].id, s->nodes);
        return FL_OK;
    }
    range *stack = fl_alloc_array(s->node_count, sizeof *stack);
    if (!stack) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the hierarchy");
    fl_status st = FL_OK;
    stack[top++] = (range){0, n, 0};
    while (top > 0) {
        range r = stack[--top];
        fl_sweep_node *node = s->nodes + r.node;
        span[2 * (size_t)r.node] = (uint32_t)r.start;
        span[2 * (size_t)r.node + 1] = (uint32_t)r.end;
        size_t mid = r.start + (r.end - r.start) / 2;
        select_median(split, widest_axis(split, r.start, r.end), r.start, mid, r.end);
        node->element = FL_SWEEP_LEAF;
        range half[2] = {{r.start, mid, 0}, {mid, r.end, 0}};
        for (int k = 0; k < 2; k++) {
            if (half[k].end - half[k].start == 1) {
                half[k].node = (uint32_t)(n - 1 + half[k].start);
                set_leaf(mesh, split[half[k].start].id, s->nodes + half[k].node);
            } else {
                half[k].node = (uint32_t)next++;
                stack[top++] = half[k];
            }
            node->child[k] = half[k].node;
        }
        if (((r.node + 1) & 0xffff) == 0 && opt &&
            fl_progress(opt->progress, opt->progress_user, "sweep hierarchy",
                        (double)r.node / (double)n)) {
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
            break;
        }
    }
    free(stack);
    return st;
}

/* Fits every internal node's element, children before parents (reverse creation order), so
 * that max_distance_below finds the subtree finished. */
static fl_status fit_nodes(fl_sweep *s, const uint32_t *span, fl_error *err)
{
    double *uv = fl_alloc_array(FL_SWEEP_SAMPLE, 6 * sizeof *uv);
    double *pts = fl_alloc_array(FL_SWEEP_SAMPLE, 9 * sizeof *pts);
    bound_entry *stack = fl_alloc_array(s->node_count, sizeof *stack);
    const fl_sweep_node *leaves = s->nodes + (s->elements - 1);
    fl_status st = FL_OK;
    if (!uv || !pts || !stack) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the hierarchy");
    } else {
        for (size_t i = s->elements - 1; i-- > 0;)
            fit_node(s, (uint32_t)i, leaves, span[2 * i], span[2 * i + 1], pts, uv, stack);
    }
    free(uv);
    free(pts);
    free(stack);
    return st;
}

/* Maps the whole pages of a block the build writes in full (the node array; the box array,
 * first the splits' scratch, then the boxes) in one call instead of one first-touch fault a
 * page: ~20 µs a fault on this paravirtualised machine made the npm bunny's first build in a
 * process 3x its warm build (issue #9). Runs after fl_sweep_advise_huge, so large blocks still
 * get huge pages. A hint: its result is ignored (kernels before 5.14 lack it). */
static void prefault(void *p, size_t bytes)
{
#ifdef MADV_POPULATE_WRITE
    uintptr_t first = ((uintptr_t)p + 4095) & ~(uintptr_t)4095;
    uintptr_t last = ((uintptr_t)p + bytes) & ~(uintptr_t)4095;
    if (p && last > first) (void)madvise((void *)first, last - first, MADV_POPULATE_WRITE);
#else
    (void)p, (void)bytes;
#endif
}

/* The hierarchy in two passes (issue #9: the build was 2-3x CGAL's): the median splits need
 * only the centroids, so they run first on 32-byte records; then the elements are fitted
 * bottom-up, reading each node's triangles from its contiguous run of leaves. */
static fl_status build_tree(fl_sweep *s, const fl_mesh *mesh, const fl_sweep_options *opt,
                            fl_error *err)
{
    /* The split records (32 bytes a triangle) and the ranges (8) are scratch in the box array
     * (64 bytes a node, 2n - 1 nodes: room for 40n), which is filled only at the end by
     * fl_sweep_compute_boxes: its pages are touched once for both uses, where separate blocks
     * would each pay a first-touch fault a page (tens of µs on this machine; issue #9). The
     * boxes are optional, so without them the scratch gets its own block. */
    size_t n = s->elements;
    s->box = fl_sweep_box_alloc(s->node_count);
    void *own = NULL, *scratch = s->box;
    if (scratch) {
        fl_sweep_advise_huge(scratch, s->node_count * sizeof *s->box);
        prefault(scratch, s->node_count * sizeof *s->box);
    } else
        scratch = own = fl_alloc_array(n, sizeof(split_rec) + 2 * sizeof(uint32_t));
    if (!scratch) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu triangles", n);
    split_rec *split = scratch;
    uint32_t *span = (uint32_t *)(split + n); /* internal nodes only */
    for (size_t t = 0; t < n; t++) {
        const uint32_t *tri = mesh->tri + 3 * t;
        split[t].id = (uint32_t)t;
        for (int c = 0; c < 3; c++)
            split[t].centroid[c] =
                (mesh->xyz[3 * (size_t)tri[0] + c] + mesh->xyz[3 * (size_t)tri[1] + c] +
                 mesh->xyz[3 * (size_t)tri[2] + c]) /
                3;
    }
    fl_status st = split_ranges(s, mesh, split, span, opt, err);
    if (st == FL_OK) st = fit_nodes(s, span, err);
    free(own);
    return st;
}

fl_status fl_sweep_build(const fl_mesh *mesh, const fl_sweep_options *opt, fl_sweep **out,
                         fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "output pointer is NULL");
    *out = NULL;
    fl_status st = check_mesh(mesh, err);
    if (st != FL_OK) return st;
    size_t n = mesh->triangle_count;
    fl_sweep *s = NULL;
    st = fl_sweep_alloc(3, 1, n, &s, err);
    if (st == FL_OK) {
        fl_sweep_advise_huge(s->nodes, s->node_count * sizeof *s->nodes);
        prefault(s->nodes, s->node_count * sizeof *s->nodes);
        for (size_t v = 0; v < 3 * mesh->vertex_count; v++)
            s->scale = fmax(s->scale, fabs(mesh->xyz[v]));
        st = build_tree(s, mesh, opt, err);
    }
    if (st == FL_OK) { /* the topology, for fl_sweep_update_vertices */
        s->tri = fl_alloc_array(n, 3 * sizeof *s->tri);
        s->vertex_count = mesh->vertex_count;
        if (s->tri)
            memcpy(s->tri, mesh->tri, 3 * n * sizeof *s->tri);
        else
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu triangles", n);
    }
    if (st != FL_OK) {
        fl_sweep_free(s);
        return st;
    }
    fl_sweep_compute_boxes(s);
    *out = s;
    return FL_OK;
}
