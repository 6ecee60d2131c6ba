/* The protecting balls B of a closed triangle mesh (Cheng & Tan §4): every ball centred at p
 * on the mesh has radius r(p) = min(gamma lgs(p), rmax) with gamma < 1/2, and the balls of
 * each vertex, edge and triangle cover it.
 *
 * Why this gives conditions C1 and C2 of Theorem 5 (so K_B subdivides the mesh):
 *  - two balls meet only if |z_i - z_j| < r_i + r_j < max(lgs(z_i), lgs(z_j)), say lgs(z_i);
 *    then every element containing z_j contains z_i (else lgs(z_i) <= |z_i - z_j|), so the
 *    carriers are nested, and balls with a common point have carriers forming a chain: conv(z_X)
 *    lies in the largest (C1). Likewise a ball meeting an element has its centre in it (C2, left).
 *  - coverage (C2, right) holds by construction below.
 *
 * The construction differs from Algorithm 1 (which inserts balls at positive restricted Voronoi
 * vertices) but keeps its order (vertices, edges, triangles) and radius rule: an edge is
 * bisected until each piece lies in one endpoint ball or within 0.9 r of its midpoint's ball;
 * a triangle is split 4-to-1 until each piece lies in one ball of its boundary or within
 * 0.9 r of its centroid's ball. Termination (as Lemma 12): the boundary balls cover the
 * boundary of each element with a margin of 0.1 r, and away from that margin lgs is bounded
 * below on a compact set, so pieces stop shrinking. Degenerate input (lgs -> 0) would still
 * recurse deeply, hence the explicit caps on depth and work (FL_ERR_ALGORITHM/FL_ERR_INPUT). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "skin/skin_sampler.h"

enum { EDGE_DEPTH = 48, TRI_DEPTH = 30, STACK = 3 * TRI_DEPTH + 8 };

typedef skin_sampler sampler;

static int cmp_edge(const void *pa, const void *pb)
{
    const uint32_t *a = pa, *b = pb;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return (a[1] > b[1]) - (a[1] < b[1]);
}

static double dist(const double *a, const double *b)
{
    double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
    return sqrt(d0 * d0 + d1 * d1 + d2 * d2);
}

fl_status skin_sampler_push(sampler *s, const double *p, double r, uint8_t kind, uint32_t id,
                            fl_error *err)
{
    if (s->balls.count >= s->max_balls)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "skin: more than %zu protecting balls; choose a larger epsilon than %g",
                       s->max_balls, s->rmax);
    if (!(r > 0))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "skin: zero local gap size at (%g, %g, %g): coincident vertices or "
                       "touching elements",
                       p[0], p[1], p[2]);
    double b[4] = {p[0], p[1], p[2], r * r};
    if (fl_vec_push(&s->balls, b, 1) || fl_vec_push(&s->carrier, &kind, 1) ||
        fl_vec_push(&s->cid, &id, 1))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (protecting balls)");
    return FL_OK;
}

double skin_sampler_radius(sampler *s, const double *p, int kind, const uint32_t *ids, size_t tri)
{
    return fmin(s->gamma * skin_eps_lgs(&s->grid, p, kind, ids, tri, s->reach), s->rmax);
}

/* 1 when every point pts[0..n) is within f times the radius of ball b. */
static int within(const double *b, const double *const *pts, int n, double f)
{
    double r = f * sqrt(b[3]);
    for (int i = 0; i < n; i++)
        if (!(dist(b, pts[i]) <= r)) return 0;
    return 1;
}

fl_status skin_sampler_tick(sampler *s, int depth, int cap, fl_error *err)
{
    if (++s->work > s->max_work || depth > cap)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "skin: covering the mesh by protecting balls needed more than %s; the "
                       "local gap size is too small for epsilon %g (near-degenerate input?)",
                       depth > cap ? "the depth cap" : "the work cap", s->rmax);
    return FL_OK;
}

static fl_status sample_edge(sampler *s, size_t e, fl_error *err)
{
    const uint32_t *ids = s->edge + 2 * e;
    const double *a = s->m->xyz + 3 * (size_t)ids[0], *b = s->m->xyz + 3 * (size_t)ids[1];
    struct {
        double s0, s1;
        int depth;
    } stack[EDGE_DEPTH + 4];
    int top = 0;
    stack[top].s0 = 0;
    stack[top].s1 = 1;
    stack[top++].depth = 0;
    while (top > 0) {
        double s0 = stack[top - 1].s0, s1 = stack[top - 1].s1;
        int depth = stack[--top].depth;
        fl_status st = skin_sampler_tick(s, depth, EDGE_DEPTH, err);
        if (st) return st;
        double p0[3], p1[3], mid[3];
        for (int c = 0; c < 3; c++) {
            p0[c] = a[c] + s0 * (b[c] - a[c]);
            p1[c] = a[c] + s1 * (b[c] - a[c]);
            mid[c] = 0.5 * (p0[c] + p1[c]);
        }
        const double *pts[2] = {p0, p1};
        const double *bb = s->balls.data;
        if (within(bb + 4 * (size_t)s->vball[ids[0]], pts, 2, 0.9) ||
            within(bb + 4 * (size_t)s->vball[ids[1]], pts, 2, 0.9))
            continue;
        double r = skin_sampler_radius(s, mid, 1, ids, 0);
        if (0.5 * dist(p0, p1) <= 0.9 * r) {
            if ((st = skin_sampler_push(s, mid, r, 1, (uint32_t)e, err))) return st;
            continue;
        }
        double sm = 0.5 * (s0 + s1);
        stack[top].s0 = sm;
        stack[top].s1 = s1;
        stack[top++].depth = depth + 1;
        stack[top].s0 = s0;
        stack[top].s1 = sm;
        stack[top++].depth = depth + 1;
    }
    return FL_OK;
}

size_t skin_sampler_edge_index(const sampler *s, uint32_t a, uint32_t b)
{
    uint32_t key[2] = {a < b ? a : b, a < b ? b : a};
    const uint32_t *hit = bsearch(key, s->edge, s->ne, 2 * sizeof(uint32_t), cmp_edge);
    return (size_t)(hit - s->edge) / 2;
}

/* 1 when the piece pts[3] lies within one ball of the triangle's boundary (list bl[nb]). */
static int boundary_covers(const sampler *s, const size_t *bl, size_t nb, const double *const *pts)
{
    const double *bb = s->balls.data;
    double c[3];
    for (int k = 0; k < 3; k++) c[k] = (pts[0][k] + pts[1][k] + pts[2][k]) / 3;
    for (size_t i = 0; i < nb; i++) {
        const double *b = bb + 4 * bl[i];
        double r = sqrt(b[3]);
        if (dist(b, c) > r) continue;
        if (within(b, pts, 3, 1 - 1e-9)) return 1;
    }
    return 0;
}

static fl_status sample_triangle(sampler *s, size_t f, fl_vec *bl, fl_error *err)
{
    const uint32_t *t = s->m->tri + 3 * f;
    bl->count = 0;
    for (int j = 0; j < 3; j++) {
        size_t vb = s->vball[t[j]], e = skin_sampler_edge_index(s, t[j], t[(j + 1) % 3]);
        if (fl_vec_push(bl, &vb, 1)) goto nomem;
        for (size_t i = s->edge_first[e]; i < s->edge_first[e + 1]; i++)
            if (fl_vec_push(bl, &i, 1)) goto nomem;
    }
    struct {
        double p[3][3];
        int depth;
    } stack[STACK];
    int top = 1;
    for (int j = 0; j < 3; j++)
        memcpy(stack[0].p[j], s->m->xyz + 3 * (size_t)t[j], 3 * sizeof(double));
    stack[0].depth = 0;
    while (top > 0) {
        double p[3][3];
        memcpy(p, stack[top - 1].p, sizeof p);
        int depth = stack[--top].depth;
        fl_status st = skin_sampler_tick(s, depth, TRI_DEPTH, err);
        if (st) return st;
        const double *pts[3] = {p[0], p[1], p[2]};
        if (boundary_covers(s, bl->data, bl->count, pts)) continue;
        double c[3], far = 0;
        for (int k = 0; k < 3; k++) c[k] = (p[0][k] + p[1][k] + p[2][k]) / 3;
        for (int j = 0; j < 3; j++) far = fmax(far, dist(c, p[j]));
        double r = skin_sampler_radius(s, c, 2, t, f);
        if (far <= 0.9 * r) {
            if ((st = skin_sampler_push(s, c, r, 2, (uint32_t)f, err))) return st;
            continue;
        }
        double m[3][3]; /* m[j] = midpoint of p[j] p[j+1] */
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++) m[j][k] = 0.5 * (p[j][k] + p[(j + 1) % 3][k]);
        const double *kids[4][3] = {{p[0], m[0], m[2]}, {m[0], p[1], m[1]},
                                    {m[2], m[1], p[2]}, {m[0], m[1], m[2]}};
        for (int q = 0; q < 4; q++) {
            for (int j = 0; j < 3; j++) memcpy(stack[top].p[j], kids[q][j], 3 * sizeof(double));
            stack[top++].depth = depth + 1;
        }
    }
    return FL_OK;
nomem:
    return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (protecting balls)");
}

static fl_status build_edges(sampler *s, fl_error *err)
{
    const fl_mesh *m = s->m;
    s->edge = fl_alloc_array(m->triangle_count * 3, 2 * sizeof(uint32_t));
    s->vball = fl_alloc_array(m->vertex_count ? m->vertex_count : 1, sizeof(uint32_t));
    if (!s->edge || !s->vball)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (edges)");
    for (size_t f = 0; f < m->triangle_count; f++)
        for (int j = 0; j < 3; j++) {
            uint32_t a = m->tri[3 * f + j], b = m->tri[3 * f + (j + 1) % 3];
            s->edge[2 * s->ne] = a < b ? a : b;
            s->edge[2 * s->ne++ + 1] = a < b ? b : a;
        }
    qsort(s->edge, s->ne, 2 * sizeof(uint32_t), cmp_edge);
    size_t u = 0;
    for (size_t i = 0; i < s->ne; i++)
        if (u == 0 || cmp_edge(s->edge + 2 * i, s->edge + 2 * (u - 1))) {
            s->edge[2 * u] = s->edge[2 * i];
            s->edge[2 * u++ + 1] = s->edge[2 * i + 1];
        }
    s->ne = u;
    s->edge_first = fl_alloc_array(u + 1, sizeof(size_t));
    if (!s->edge_first) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (edges)");
    return FL_OK;
}

static fl_status run(sampler *s, int alg1, fl_error *err)
{
    fl_status st = build_edges(s, err);
    if (!st) st = skin_eps_grid_build(s->m, s->reach, &s->grid, err);
    /* vertices (the mesh is closed, so every vertex is on a triangle) */
    for (size_t v = 0; v < s->m->vertex_count && !st; v++) {
        uint32_t id = (uint32_t)v;
        s->vball[v] = (uint32_t)s->balls.count;
        const double *p = s->m->xyz + 3 * v;
        st = skin_sampler_push(s, p, skin_sampler_radius(s, p, 0, &id, 0), 0, id, err);
    }
    for (size_t e = 0; e < s->ne && !st; e++) {
        s->edge_first[e] = s->balls.count;
        st = alg1 ? skin_alg1_edge(s, e, err) : sample_edge(s, e, err);
    }
    if (!st) s->edge_first[s->ne] = s->balls.count;
    fl_vec bl;
    fl_vec_init(&bl, sizeof(size_t));
    for (size_t f = 0; f < s->m->triangle_count && !st; f++)
        st = alg1 ? skin_alg1_triangle(s, f, &bl, err) : sample_triangle(s, f, &bl, err);
    fl_vec_free(&bl);
    return st;
}

void skin_eps_sample_free(skin_eps_sample *s)
{
    if (!s) return;
    fl_balls_free(&s->balls);
    free(s->carrier);
    free(s->carrier_id);
    memset(s, 0, sizeof *s);
}

fl_status skin_eps_surface_balls(const fl_mesh *m, double rmax, double gamma, size_t max_balls,
                                 int placement, skin_eps_sample *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    sampler s;
    memset(&s, 0, sizeof s);
    s.m = m;
    s.rmax = rmax;
    s.gamma = gamma;
    s.reach = rmax / gamma * 1.01;
    s.max_balls = max_balls;
    s.max_work = 64 * max_balls + 64 * m->triangle_count;
    fl_vec_init(&s.balls, 4 * sizeof(double));
    fl_vec_init(&s.carrier, 1);
    fl_vec_init(&s.cid, sizeof(uint32_t));
    fl_status st = run(&s, placement == FL_SKIN_PLACE_ALGORITHM1, err);
    if (!st) {
        out->boundary_count = s.edge_first[s.ne];
        out->balls.count = s.balls.count;
        out->balls.xyzw = fl_vec_release(&s.balls);
        out->carrier = fl_vec_release(&s.carrier);
        out->carrier_id = fl_vec_release(&s.cid);
    }
    fl_vec_free(&s.balls);
    fl_vec_free(&s.carrier);
    fl_vec_free(&s.cid);
    free(s.edge);
    free(s.vball);
    free(s.edge_first);
    skin_eps_grid_free(&s.grid);
    return st;
}
