/* The mesh hierarchy: a binary tree over the triangles whose bounding volumes are triangles
 * swept by spheres, the volume type of §4.1. Simplification (documented in docs/sweep.md):
 * Guéziec obtains the hierarchy from error-bounded edge collapses and refines it by vertex
 * splits (§4.2); here it is built top-down by median splits of the triangle centroids, and
 * each internal node gets its own bounding triangle: a triangle in the principal plane of the
 * node's vertices enclosing their projection, with ε = the largest distance of a vertex to it.
 * The swept volume is convex, so containing the vertices it contains their triangles, and the
 * priority process of §3.2 runs on it unchanged. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "sweep/sweep_internal.h"

typedef struct range {
    size_t start, end; /* triangles rec[start..end) */
    uint32_t node;
} range;

/* A triangle during the build: its corners and centroid inline, so that the median splits
 * move the records themselves and every pass over a node's triangles streams through memory
 * (an index array into the mesh made the build wait on cache misses, issue #9). */
typedef struct tri_rec {
    double c[9];
    double centroid[3];
    uint32_t id;
} tri_rec;

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

/* A frame for a node of a few triangles without the eigen-solve: the normal is their summed
 * (area-weighted) normal, e[0] the first triangle's first edge in that plane. Near the leaves
 * this fixed cost per node dominated the build (issue #9). Returns 0 when the triangles are
 * too degenerate or large for it; the caller then fits the principal frame. */
static int normal_frame(const tri_rec *rec, size_t start, size_t end, double e[3][3])
{
    double nrm[3] = {0, 0, 0};
    for (size_t i = start; i < end; i++) {
        const double *c = rec[i].c;
        double a[3] = {c[3] - c[0], c[4] - c[1], c[5] - c[2]};
        double b[3] = {c[6] - c[0], c[7] - c[1], c[8] - c[2]};
        nrm[0] += a[1] * b[2] - a[2] * b[1];
        nrm[1] += a[2] * b[0] - a[0] * b[2];
        nrm[2] += a[0] * b[1] - a[1] * b[0];
    }
    double len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (!(len > 0) || !isfinite(len)) return 0;
    const double *c = rec[start].c;
    double d[3] = {c[3] - c[0], c[4] - c[1], c[5] - c[2]}, h = 0, u2 = 0, d2 = 0;
    for (int k = 0; k < 3; k++) {
        e[2][k] = nrm[k] / len;
        h += d[k] * e[2][k];
    }
    for (int k = 0; k < 3; k++) {
        d2 += d[k] * d[k];
        d[k] -= h * e[2][k];
        u2 += d[k] * d[k];
    }
    if (!(u2 > 1e-12 * d2) || !isfinite(d2)) return 0;
    double inv = 1 / sqrt(u2);
    for (int k = 0; k < 3; k++)
        e[0][k] = d[k] * inv;
    e[1][0] = e[2][1] * e[0][2] - e[2][2] * e[0][1];
    e[1][1] = e[2][2] * e[0][0] - e[2][0] * e[0][2];
    e[1][2] = e[2][0] * e[0][1] - e[2][1] * e[0][0];
    return 1;
}

/* Gathers the corners of every stride-th triangle of rec[start..end) into pts (9 doubles a
 * triangle, so the passes below stream through memory) and returns the principal frame of
 * these points (their count is returned): mean
 * and axes e[0], e[1] (largest spread first) and the normal e[2]. One pass: moments about the
 * first point (shifted, so that a mesh far from the origin does not cancel the covariance);
 * the frame only shapes the element, whose radius is measured afterwards. */
static size_t gather_frame(const tri_rec *rec, size_t start, size_t end, size_t stride, double *pts,
                           double *mean, double e[3][3])
{
    const double *ref = rec[start].c;
    double sum[3] = {0, 0, 0}, s2[6] = {0, 0, 0, 0, 0, 0};
    size_t n = 0;
    for (size_t i = start; i < end; i += stride) {
        const double *t = rec[i].c;
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
    if (end - start <= 3 && normal_frame(rec, start, end, e)) return n;
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
 * every vertex below it, so it is a large part of the build). */
static void enclosing_triangle(const double *uv, size_t n, const double *lo, const double *hi,
                               double tri[3][2])
{
    static const int axis[4][2] = {{0, 1}, {0, 1}, {1, 0}, {1, 0}}; /* (x, y) from (u, v) */
    static const double flip[4] = {1, -1, 1, -1};
    static const double factor[3] = {0.5, 1, 2};
    double y0[4], slope[4][3], inv[4][3], left[4][3], right[4][3];
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
            for (int k = 0; k < 3; k++) {
                double t = y * inv[o][k], l = x - t, r = x + t;
                left[o][k] = l < left[o][k] ? l : left[o][k];
                right[o][k] = r > right[o][k] ? r : right[o][k];
            }
        }
    }
    double best = INFINITY;
    for (int o = 0; o < 4; o++)
        for (int k = 0; k < 3; k++) {
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

/* Squared distance from p to the triangle v[0..8], with a fast path for the common case of a
 * point whose projection falls well inside it (every node vertex does, the triangle encloses
 * their projections): then the distance is the distance to the plane. Barycentrics above
 * 1e-6 leave no doubt which case applies despite rounding; the rest go through the full
 * closest-point routine. */
typedef struct tri_frame {
    double a[3], b[3], nrm[3], d00, d01, d11, inv_denom;
    int ok;
} tri_frame;

static void tri_frame_init(tri_frame *f, const double *v)
{
    double n2 = 0;
    for (int c = 0; c < 3; c++) {
        f->a[c] = v[3 + c] - v[c];
        f->b[c] = v[6 + c] - v[c];
    }
    f->nrm[0] = f->a[1] * f->b[2] - f->a[2] * f->b[1];
    f->nrm[1] = f->a[2] * f->b[0] - f->a[0] * f->b[2];
    f->nrm[2] = f->a[0] * f->b[1] - f->a[1] * f->b[0];
    f->d00 = f->d01 = f->d11 = 0;
    for (int c = 0; c < 3; c++) {
        n2 += f->nrm[c] * f->nrm[c];
        f->d00 += f->a[c] * f->a[c];
        f->d01 += f->a[c] * f->b[c];
        f->d11 += f->b[c] * f->b[c];
    }
    double denom = f->d00 * f->d11 - f->d01 * f->d01;
    f->ok = n2 > 0 && denom > 0 && isfinite(1 / denom) && isfinite(1 / sqrt(n2));
    if (!f->ok) return;
    f->inv_denom = 1 / denom;
    double inv_len = 1 / sqrt(n2);
    for (int c = 0; c < 3; c++) f->nrm[c] *= inv_len;
}

static double tri_dist2(const tri_frame *f, const double *v, const double *p)
{
    if (f->ok) {
        double w[3] = {p[0] - v[0], p[1] - v[1], p[2] - v[2]};
        double d20 = w[0] * f->a[0] + w[1] * f->a[1] + w[2] * f->a[2];
        double d21 = w[0] * f->b[0] + w[1] * f->b[1] + w[2] * f->b[2];
        double beta = (f->d11 * d20 - f->d01 * d21) * f->inv_denom;
        double gamma = (f->d00 * d21 - f->d01 * d20) * f->inv_denom;
        if (beta > 1e-6 && gamma > 1e-6 && 1 - beta - gamma > 1e-6) {
            double h = w[0] * f->nrm[0] + w[1] * f->nrm[1] + w[2] * f->nrm[2];
            return h * h;
        }
    }
    double bary[3], closest[3];
    return fl_sweep_triangle_closest(p, v, v + 3, v + 6, bary, closest);
}

/* Triangles of a node that shape its bounding triangle (below). */
#define FL_SWEEP_SAMPLE 128

/* The bounding element of a node: a triangle in the principal plane of the node's vertices
 * (at the mid-plane of their spread along the normal) enclosing their projections, and ε =
 * the farthest vertex from it. Large nodes shape the triangle on a sample of at most
 * FL_SWEEP_SAMPLE of their triangles (every k-th in the median-split order, so spread over
 * the node): ε is measured on EVERY vertex afterwards, so the element contains the node
 * whatever the sample; a vertex the sample misses only widens ε. This turns the build's
 * several passes over every vertex per tree level into one (issue #9: build ≤ 2× CGAL).
 * Also rep, the vertex nearest to the sample's mean: a point of the shape inside the element,
 * whose distance bounds the distance to the node's triangles from above (query.c). pts and uv
 * are scratch room for 9 and 6 doubles a sampled triangle. */
static void bounding_triangle(const tri_rec *rec, size_t start, size_t end, double scale,
                              double *pts, double *uv, fl_sweep_node *node)
{
    double mean[3], e[3][3], lo[3] = {INFINITY, INFINITY, INFINITY};
    double hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    size_t stride = (end - start + FL_SWEEP_SAMPLE - 1) / FL_SWEEP_SAMPLE;
    size_t n = gather_frame(rec, start, end, stride, pts, mean, e);
    for (size_t i = 0; i < n; i++) {
        const double *p = pts + 3 * i;
        for (int a = 0; a < 3; a++) {
            double x = (p[0] - mean[0]) * e[a][0] + (p[1] - mean[1]) * e[a][1] +
                       (p[2] - mean[2]) * e[a][2];
            if (a < 2) uv[2 * i + a] = x;
            lo[a] = x < lo[a] ? x : lo[a]; /* not fmin/fmax: libm calls, and x is finite */
            hi[a] = x > hi[a] ? x : hi[a];
        }
    }
    double corner[3][2], mid_n = (lo[2] + hi[2]) / 2;
    enclosing_triangle(uv, n, lo, hi, corner);
    for (int k = 0; k < 3; k++)
        for (int c = 0; c < 3; c++)
            node->v[3 * k + c] =
                mean[c] + corner[k][0] * e[0][c] + corner[k][1] * e[1][c] + mid_n * e[2][c];
    /* Measured against the stored triangle, not derived from the frame, so rounding in the
     * frame cannot shrink it. */
    double eps2 = 0, best = INFINITY;
    tri_frame f;
    tri_frame_init(&f, node->v);
    for (size_t i = start; i < end; i++) {
        for (int k = 0; k < 3; k++) {
            const double *p = rec[i].c + 3 * k;
            double d2 = tri_dist2(&f, node->v, p);
            eps2 = d2 > eps2 ? d2 : eps2;
            double r2 = (p[0] - mean[0]) * (p[0] - mean[0]) +
                        (p[1] - mean[1]) * (p[1] - mean[1]) + (p[2] - mean[2]) * (p[2] - mean[2]);
            if (r2 < best) {
                best = r2;
                node->rep[0] = p[0], node->rep[1] = p[1], node->rep[2] = p[2];
            }
        }
    }
    node->eps = fl_sweep_widen(sqrt(eps2), scale);
}

/* Reorders rec[start..end) so that rec[mid] has the median centroid coordinate `axis` and
 * smaller ones precede it (Hoare quickselect). */
static void select_median(tri_rec *rec, int axis, size_t start, size_t mid, size_t end)
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
                tri_rec tmp = rec[i];
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

static int widest_axis(const tri_rec *rec, size_t start, size_t end)
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

static void set_leaf(const tri_rec *rec, fl_sweep_node *node)
{
    memcpy(node->v, rec->c, 9 * sizeof *node->v);
    node->eps = 0;
    node->child[0] = node->child[1] = FL_SWEEP_LEAF;
    node->element = rec->id;
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

/* Splits triangle ranges top-down; nodes are numbered in creation order, root first. */
static fl_status split_ranges(fl_sweep *s, tri_rec *rec, const fl_sweep_options *opt,
                              fl_error *err)
{
    range *stack = fl_alloc_array(s->node_count, sizeof *stack);
    double *uv = fl_alloc_array(FL_SWEEP_SAMPLE, 6 * sizeof *uv);
    double *pts = fl_alloc_array(FL_SWEEP_SAMPLE, 9 * sizeof *pts);
    fl_status st = FL_OK;
    if (!stack || !uv || !pts)
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the hierarchy");
    size_t top = 0, next = 1, done = 0;
    if (st == FL_OK) stack[top++] = (range){0, s->elements, 0};
    while (top > 0) {
        range r = stack[--top];
        fl_sweep_node *node = s->nodes + r.node;
        if (r.end - r.start == 1) {
            set_leaf(rec + r.start, node);
            if ((++done & 0xffff) == 0 && opt &&
                fl_progress(opt->progress, opt->progress_user, "sweep hierarchy",
                            (double)done / (double)s->elements)) {
                st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
                break;
            }
            continue;
        }
        bounding_triangle(rec, r.start, r.end, s->scale, pts, uv, node);
        size_t mid = r.start + (r.end - r.start) / 2;
        select_median(rec, widest_axis(rec, r.start, r.end), r.start, mid, r.end);
        node->element = FL_SWEEP_LEAF;
        node->child[0] = (uint32_t)next;
        node->child[1] = (uint32_t)(next + 1);
        stack[top++] = (range){r.start, mid, (uint32_t)next};
        stack[top++] = (range){mid, r.end, (uint32_t)(next + 1)};
        next += 2;
    }
    free(stack);
    free(uv);
    free(pts);
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
    tri_rec *rec = fl_alloc_array(n, sizeof *rec);
    fl_sweep *s = NULL;
    if (!rec) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu triangles", n);
    } else {
        st = fl_sweep_alloc(3, 1, n, &s, err);
    }
    if (st == FL_OK) {
        for (size_t v = 0; v < 3 * mesh->vertex_count; v++)
            s->scale = fmax(s->scale, fabs(mesh->xyz[v]));
        for (size_t t = 0; t < n; t++) {
            tri_rec *r = rec + t;
            r->id = (uint32_t)t;
            for (int k = 0; k < 3; k++)
                memcpy(r->c + 3 * k, mesh->xyz + 3 * (size_t)mesh->tri[3 * t + k],
                       3 * sizeof *r->c);
            for (int c = 0; c < 3; c++)
                r->centroid[c] = (r->c[c] + r->c[3 + c] + r->c[6 + c]) / 3;
        }
        st = split_ranges(s, rec, opt, err);
    }
    if (st == FL_OK) { /* the topology, for fl_sweep_update_vertices */
        s->tri = fl_alloc_array(n, 3 * sizeof *s->tri);
        s->vertex_count = mesh->vertex_count;
        if (s->tri)
            memcpy(s->tri, mesh->tri, 3 * n * sizeof *s->tri);
        else
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu triangles", n);
    }
    free(rec);
    if (st != FL_OK) {
        fl_sweep_free(s);
        return st;
    }
    fl_sweep_compute_boxes(s);
    *out = s;
    return FL_OK;
}
