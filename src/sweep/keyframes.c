/* Key-frame deformation of a mesh (Guéziec §5.3, first method): "each vertex is linearly
 * interpolated between key-frames. Before the deformation starts, the sphere radii defining
 * the bounding volumes corresponding to each key frame are recorded, each in a separate
 * array. [...] During the deformation, radii are linearly interpolated between key-frames."
 *
 * Here every node stores, per key frame f, a base triangle B_f (corners b_k,f) and a radius
 * ε_f with every vertex of the node at frame f within ε_f of B_f. Between frames f and f + 1,
 * at s in [0,1], the vertices are x(s) = (1−s) x_f + s x_{f+1}, the base is the corner-wise
 * interpolation B(s) and the radius
 *
 *     ε(s) = (1−s) ε_f + s ε_{f+1} + s(1−s) D,   D = max_{j,k} |d_j − d_k|,  d_k = b_k,f+1 − b_k,f.
 *
 * Why the correction: let c_f = Σ λ_k b_k,f be the point of B_f nearest x_f and
 * c_{f+1} = Σ μ_k b_k,f+1 that of B_{f+1} nearest x_{f+1}. The point with barycentrics
 * ν = (1−s)λ + sμ lies in B(s), and a short expansion gives
 *     Σ ν_k b_k(s) − [(1−s) c_f + s c_{f+1}] = s(1−s) Σ (λ_k − μ_k) d_k.
 * Σ(λ_k − μ_k) = 0, so the sum is w·(a convex combination of the d_k minus another one) with
 * w ≤ 1, whose length is at most D. Hence
 *     dist(x(s), B(s)) ≤ |(1−s)(x_f − c_f) + s(x_{f+1} − c_{f+1})| + s(1−s) D ≤ ε(s).
 * Plain interpolation of the radii (D = 0) is right only when the base triangle translates;
 * a rotating base needs the correction (docs/sweep.md shows a case). The swept volume is
 * convex and contains the node's vertices at time s, so it contains its triangles at time s
 * (each is the hull of its interpolated corners): the §3.2 invariant, and the queries of
 * query.c answer exactly. Rounding of the interpolation is a few ulps of the coordinates,
 * far inside fl_sweep_widen's 64.
 *
 * The per-frame bases come from carrying the frame-0 hierarchy from frame to frame with
 * fl_sweep_update_vertices (deform.c: each base moved by the rigid motion fitted to its
 * vertices); the radii are then measured exactly on every vertex of the frame (the paper's
 * "computing error bounds" with the known hierarchy). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "sweep/sweep_internal.h"

/* Per node and key frame: the base triangle's corners, then the radius. */
#define KF_STRIDE 10

struct fl_sweep_keyframes {
    fl_sweep *s;
    size_t frames, nv;
    double *xyz;     /* frames * 3 * nv: the key frames */
    double *table;   /* frames * node_count * KF_STRIDE */
    uint32_t *rep;   /* per node: a vertex of the node, its representative at every time */
    uint32_t *up;    /* per node: its parent (the root: UINT32_MAX) */
    double t;        /* the current time */
};

static fl_status check_input(const fl_mesh *mesh, const double *frames, size_t frame_count,
                             fl_sweep_keyframes **out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "output pointer is NULL");
    *out = NULL;
    if (!mesh || !frames)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "mesh and frames must not be NULL");
    if (frame_count == 0) return fl_fail(err, FL_ERR_INPUT, NULL, -1, "no key frame given");
    size_t per = 3 * mesh->vertex_count;
    if (mesh->vertex_count > SIZE_MAX / 3 || (per && frame_count > SIZE_MAX / sizeof(double) / per))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "too many key-frame coordinates");
    for (size_t i = 0; i < per * frame_count; i++)
        if (!fl_sweep_coord_ok(frames[i]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "key frame %zu, vertex %zu is not finite or beyond 1e150", i / per,
                           i % per / 3);
    return FL_OK;
}

/* Parents and representatives (the first corner of the leftmost leaf below each node). */
static void link_nodes(fl_sweep_keyframes *kf)
{
    const fl_sweep *s = kf->s;
    for (size_t i = 0; i < s->node_count; i++)
        kf->up[i] = UINT32_MAX;
    for (size_t i = 0; i < s->node_count; i++)
        if (!fl_sweep_is_leaf(s->nodes + i))
            kf->up[s->nodes[i].child[0]] = kf->up[s->nodes[i].child[1]] = (uint32_t)i;
    for (size_t i = 0; i < s->node_count; i++) {
        const fl_sweep_node *n = s->nodes + i;
        while (!fl_sweep_is_leaf(n))
            n = s->nodes + n->child[0];
        kf->rep[i] = s->tri[3 * (size_t)n->element];
    }
}

/* The exact radius of every internal node over its vertices at the current positions (the
 * leaves hold them) for the bases `base` (9 doubles a node): each leaf corner is measured
 * against all its ancestors' bases. Into eps[node], widened. */
static void exact_radii(const fl_sweep *s, const uint32_t *up, const double *base, double *eps)
{
    for (size_t i = 0; i < s->node_count; i++)
        eps[i] = 0;
    for (size_t i = 0; i < s->node_count; i++) {
        const fl_sweep_node *leaf = s->nodes + i;
        if (!fl_sweep_is_leaf(leaf)) continue;
        for (uint32_t a = up[i]; a != UINT32_MAX; a = up[a]) {
            const double *v = base + 9 * (size_t)a;
            double bary[3], closest[3];
            for (int k = 0; k < 3; k++) {
                double d2 = fl_sweep_triangle_closest(leaf->v + 3 * k, v, v + 3, v + 6, bary,
                                                      closest);
                if (d2 > eps[a]) eps[a] = d2; /* squared until the end */
            }
        }
    }
    for (size_t i = 0; i < s->node_count; i++)
        eps[i] = fl_sweep_widen(sqrt(eps[i]), s->scale);
}

/* Moments of a node's corners (with multiplicity) at frame 0 (p) and frame f (q): their
 * count, sums, Σ p pᵀ and Σ p qᵀ, summed bottom-up. */
typedef struct moments {
    double n, p[3], q[3], pp[9], pq[9];
} moments;

static void add_moments(moments *m, const moments *c)
{
    m->n += c->n;
    for (int i = 0; i < 9; i++) {
        m->pp[i] += c->pp[i];
        m->pq[i] += c->pq[i];
        if (i < 3) m->p[i] += c->p[i], m->q[i] += c->q[i];
    }
}

/* Solves (C + λI) x = y for symmetric C by Cramer's rule; λ keeps flat (coplanar) nodes
 * solvable: the direction C does not see then maps to 0, i.e. into the fitted plane. */
static void solve3(const double *c, double lambda, const double *y, double *x)
{
    double m[9];
    for (int i = 0; i < 9; i++)
        m[i] = c[i] + (i % 4 == 0 ? lambda : 0);
    double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
                 m[2] * (m[3] * m[7] - m[4] * m[6]);
    for (int k = 0; k < 3; k++) {
        double t[9];
        for (int i = 0; i < 9; i++)
            t[i] = i % 3 == k ? y[i / 3] : m[i];
        double dk = t[0] * (t[4] * t[8] - t[5] * t[7]) - t[1] * (t[3] * t[8] - t[5] * t[6]) +
                    t[2] * (t[3] * t[7] - t[4] * t[6]);
        x[k] = det != 0 && isfinite(dk / det) ? dk / det : 0;
    }
}

/* The node's frame-0 base carried by the affine map that best fits (least squares) its
 * corners' motion from frame 0 to frame f: x -> M (x − p̄) + q̄ with Mᵀ = C⁻¹ X, C and X the
 * centred Σ p pᵀ and Σ p qᵀ. Unlike a rigid motion it follows stretches and shears, which a
 * key-frame animation is full of; it is only a candidate (exactness never depends on it). */
static void affine_base(const moments *m, const double *base0, double *out)
{
    double pm[3], qm[3], c[9], x[9], trace = 0;
    for (int i = 0; i < 3; i++)
        pm[i] = m->p[i] / m->n, qm[i] = m->q[i] / m->n;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            c[3 * i + j] = m->pp[3 * i + j] - m->n * pm[i] * pm[j];
            x[3 * i + j] = m->pq[3 * i + j] - m->n * pm[i] * qm[j];
        }
    trace = c[0] + c[4] + c[8];
    double mt[9]; /* Mᵀ, column j solving C col = X col j */
    for (int j = 0; j < 3; j++) {
        double y[3] = {x[j], x[3 + j], x[6 + j]}, col[3];
        solve3(c, 1e-9 * trace + 1e-300, y, col);
        for (int i = 0; i < 3; i++)
            mt[3 * i + j] = col[i];
    }
    for (int k = 0; k < 3; k++) {
        double d[3] = {base0[3 * k] - pm[0], base0[3 * k + 1] - pm[1], base0[3 * k + 2] - pm[2]};
        for (int c2 = 0; c2 < 3; c2++)
            out[3 * k + c2] = mt[c2] * d[0] + mt[3 + c2] * d[1] + mt[6 + c2] * d[2] + qm[c2];
    }
}

/* The affine candidate bases of frame f for every internal node (leaves: their triangle). */
static fl_status affine_bases(const fl_sweep_keyframes *kf, size_t f, double *cand,
                              fl_error *err)
{
    const fl_sweep *s = kf->s;
    moments *m = fl_alloc_array(s->node_count, sizeof *m);
    if (!m) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for key frames");
    const double *x0 = kf->xyz, *xf = kf->xyz + 3 * kf->nv * f, *row0 = kf->table;
    for (size_t i = s->node_count; i-- > 0;) { /* children come after their parent */
        const fl_sweep_node *node = s->nodes + i;
        m[i] = (moments){0};
        if (!fl_sweep_is_leaf(node)) {
            add_moments(m + i, m + node->child[0]);
            add_moments(m + i, m + node->child[1]);
            affine_base(m + i, row0 + KF_STRIDE * i, cand + 9 * i);
            continue;
        }
        for (int k = 0; k < 3; k++) {
            size_t v = s->tri[3 * (size_t)node->element + k];
            const double *p = x0 + 3 * v, *q = xf + 3 * v;
            m[i].n += 1;
            for (int a = 0; a < 3; a++) {
                m[i].p[a] += p[a], m[i].q[a] += q[a];
                cand[9 * i + 3 * k + a] = q[a];
                for (int b = 0; b < 3; b++)
                    m[i].pp[3 * a + b] += p[a] * p[b], m[i].pq[3 * a + b] += p[a] * q[b];
            }
        }
    }
    free(m);
    return FL_OK;
}

/* Frame f's bases and radii: the carried (rigid-fit) base or the affine candidate, whichever
 * gives the smaller exact radius, node by node. */
static fl_status fit_frame(fl_sweep_keyframes *kf, size_t f, fl_error *err)
{
    fl_sweep *s = kf->s;
    double *cand = fl_alloc_array(s->node_count, 9 * sizeof *cand);
    double *mine = fl_alloc_array(s->node_count, 9 * sizeof *mine);
    double *e_cand = fl_alloc_array(s->node_count, sizeof *e_cand);
    double *e_mine = fl_alloc_array(s->node_count, sizeof *e_mine);
    fl_status st = cand && mine && e_cand && e_mine
                       ? affine_bases(kf, f, cand, err)
                       : fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for key frames");
    if (st == FL_OK) {
        for (size_t i = 0; i < s->node_count; i++) {
            memcpy(mine + 9 * i, s->nodes[i].v, 9 * sizeof *mine);
            /* A fit blown up by huge or nearly flat input (|x| up to 1e150 squared in the
             * moments) is no candidate: keep the distances finite. */
            for (int k = 0; k < 9; k++)
                if (!(fabs(cand[9 * i + k]) <= 1e152)) {
                    memcpy(cand + 9 * i, mine + 9 * i, 9 * sizeof *cand);
                    break;
                }
        }
        exact_radii(s, kf->up, mine, e_mine);
        exact_radii(s, kf->up, cand, e_cand);
        for (size_t i = 0; i < s->node_count; i++) {
            fl_sweep_node *node = s->nodes + i;
            if (fl_sweep_is_leaf(node)) continue;
            int take = e_cand[i] < e_mine[i];
            node->eps = take ? e_cand[i] : e_mine[i];
            if (take) memcpy(node->v, cand + 9 * i, 9 * sizeof *cand);
        }
    }
    free(cand);
    free(mine);
    free(e_cand);
    free(e_mine);
    return st;
}

static void record_frame(fl_sweep_keyframes *kf, size_t f)
{
    const fl_sweep *s = kf->s;
    double *row = kf->table + f * s->node_count * KF_STRIDE;
    for (size_t i = 0; i < s->node_count; i++) {
        memcpy(row + KF_STRIDE * i, s->nodes[i].v, 9 * sizeof(double));
        row[KF_STRIDE * i + 9] = s->nodes[i].eps;
    }
}

/* The hierarchy at every key frame, frame 0 by a build, the others by carrying it along. */
static fl_status record_frames(fl_sweep_keyframes *kf, const fl_mesh *mesh,
                               const fl_sweep_options *opt, fl_error *err)
{
    fl_mesh m0 = {mesh->vertex_count, kf->xyz, mesh->triangle_count, mesh->tri};
    fl_status st = fl_sweep_build(&m0, opt, &kf->s, err);
    if (st != FL_OK) return st;
    fl_sweep *s = kf->s;
    kf->table = fl_alloc_array(kf->frames, s->node_count * KF_STRIDE * sizeof(double));
    kf->rep = fl_alloc_array(s->node_count, sizeof *kf->rep);
    kf->up = fl_alloc_array(s->node_count, sizeof *kf->up);
    if (!kf->table || !kf->rep || !kf->up)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu key frames",
                       kf->frames);
    link_nodes(kf);
    for (size_t i = 0; i < 3 * kf->nv * kf->frames; i++) /* one slack for every frame */
        s->scale = fmax(s->scale, fabs(kf->xyz[i]));
    record_frame(kf, 0);
    for (size_t f = 1; f < kf->frames; f++) {
        st = fl_sweep_update_vertices(s, kf->xyz + 3 * kf->nv * f, err);
        if (st != FL_OK) return st;
        st = fit_frame(kf, f, err);
        if (st != FL_OK) return st;
        record_frame(kf, f);
    }
    return FL_OK;
}

fl_status fl_sweep_keyframes_new(const fl_mesh *mesh, const double *frames, size_t frame_count,
                                 const fl_sweep_options *opt, fl_sweep_keyframes **out,
                                 fl_error *err)
{
    fl_status st = check_input(mesh, frames, frame_count, out, err);
    if (st != FL_OK) return st;
    fl_sweep_keyframes *kf = calloc(1, sizeof *kf);
    if (!kf) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for key frames");
    kf->frames = frame_count;
    kf->nv = mesh->vertex_count;
    kf->xyz = fl_alloc_array(frame_count, 3 * kf->nv * sizeof(double) + (kf->nv == 0));
    if (!kf->xyz) st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for key frames");
    if (st == FL_OK) {
        memcpy(kf->xyz, frames, frame_count * 3 * kf->nv * sizeof(double));
        st = record_frames(kf, mesh, opt, err);
    }
    if (st == FL_OK) st = fl_sweep_keyframes_set_time(kf, 0, err);
    if (st != FL_OK) {
        fl_sweep_keyframes_free(kf);
        return st;
    }
    kf->s->moved = 0; /* a fresh hierarchy: nothing has moved yet for its cursors */
    kf->s->updates = 0;
    *out = kf;
    return FL_OK;
}

void fl_sweep_keyframes_free(fl_sweep_keyframes *kf)
{
    if (!kf) return;
    fl_sweep_free(kf->s);
    free(kf->xyz);
    free(kf->table);
    free(kf->rep);
    free(kf->up);
    free(kf);
}

const fl_sweep *fl_sweep_keyframes_sweep(const fl_sweep_keyframes *kf)
{
    return kf ? kf->s : NULL;
}

/* The key-frame interval [f, f + 1] holding t and the position s in it. */
static size_t locate(const fl_sweep_keyframes *kf, double t, double *s)
{
    if (kf->frames == 1) {
        *s = 0;
        return 0;
    }
    size_t f = (size_t)floor(t);
    if (f > kf->frames - 2) f = kf->frames - 2;
    *s = t - (double)f;
    return f;
}

static double lerp(double a, double b, double s)
{
    return (1 - s) * a + s * b; /* exactly a at s = 0 and b at s = 1 */
}

/* Vertex i at position s of interval f. */
static void vertex_at(const fl_sweep_keyframes *kf, size_t f, double s, size_t i, double *out)
{
    size_t g = kf->frames == 1 ? f : f + 1;
    const double *a = kf->xyz + 3 * (kf->nv * f + i), *b = kf->xyz + 3 * (kf->nv * g + i);
    for (int c = 0; c < 3; c++)
        out[c] = lerp(a[c], b[c], s);
}

fl_status fl_sweep_keyframes_vertices(const fl_sweep_keyframes *kf, double *xyz, fl_error *err)
{
    if (!kf || !xyz)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "key frames and output must not be NULL");
    double s;
    size_t f = locate(kf, kf->t, &s);
    for (size_t i = 0; i < kf->nv; i++)
        vertex_at(kf, f, s, i, xyz + 3 * i);
    return FL_OK;
}

/* An internal node at position s of interval f: interpolated base and corrected radius. */
static void interpolate_node(const fl_sweep_keyframes *kf, size_t f, double s, size_t i)
{
    fl_sweep *sw = kf->s;
    size_t g = kf->frames == 1 ? f : f + 1;
    const double *a = kf->table + (f * sw->node_count + i) * KF_STRIDE;
    const double *b = kf->table + (g * sw->node_count + i) * KF_STRIDE;
    fl_sweep_node *node = sw->nodes + i;
    double d[3][3], spread = 0;
    for (int k = 0; k < 3; k++)
        for (int c = 0; c < 3; c++) {
            node->v[3 * k + c] = lerp(a[3 * k + c], b[3 * k + c], s);
            d[k][c] = b[3 * k + c] - a[3 * k + c];
        }
    for (int j = 0; j < 3; j++)
        for (int k = j + 1; k < 3; k++) {
            double e[3] = {d[j][0] - d[k][0], d[j][1] - d[k][1], d[j][2] - d[k][2]};
            spread = fmax(spread, sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]));
        }
    double eps = lerp(a[9], b[9], s) + s * (1 - s) * spread;
    node->eps = fl_sweep_widen(eps, sw->scale);
    vertex_at(kf, f, s, kf->rep[i], node->rep);
}

fl_status fl_sweep_keyframes_set_time(fl_sweep_keyframes *kf, double t, fl_error *err)
{
    if (!kf) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "key frames must not be NULL");
    if (!(t >= 0 && t <= (double)(kf->frames - 1)))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "time %g is outside [0, %zu]", t,
                       kf->frames - 1);
    double s;
    size_t f = locate(kf, t, &s);
    fl_sweep *sw = kf->s;
    double largest = 0;
    for (size_t i = 0; i < sw->node_count; i++) {
        fl_sweep_node *node = sw->nodes + i;
        if (!fl_sweep_is_leaf(node)) {
            interpolate_node(kf, f, s, i);
            continue;
        }
        for (int k = 0; k < 3; k++) {
            double p[3], m2 = 0;
            vertex_at(kf, f, s, sw->tri[3 * (size_t)node->element + k], p);
            for (int c = 0; c < 3; c++) {
                m2 += (p[c] - node->v[3 * k + c]) * (p[c] - node->v[3 * k + c]);
                node->v[3 * k + c] = p[c];
            }
            largest = fmax(largest, sqrt(m2));
        }
    }
    if (sw->box) fl_sweep_compute_boxes(sw);
    /* §5.2: cursors widen their kept intervals by the largest vertex move (query.c); every
     * point of a triangle moves by a convex combination of its corners' moves. */
    sw->moved += fl_sweep_widen(largest, sw->scale);
    sw->updates++;
    kf->t = t;
    return FL_OK;
}
