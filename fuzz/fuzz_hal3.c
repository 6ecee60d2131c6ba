/* Fuzzes the 3D HAL (fl_hal3_*) on small closed meshes from fz_closed_mesh (perturbed
 * tetrahedra / octahedra / stellated octahedra, sometimes broken). Oracles:
 *  - validity: a mesh that fl_mesh_check finds not closed, manifold, oriented, connected, genus 0
 *    and free of degenerate triangles (or with NaN/Inf) must get FL_ERR_INPUT; a valid one must
 *    build (FL_ERR_ALGORITHM allowed: "refinement cannot proceed");
 *  - fl_hal3_contains == brute force: exact on-triangle test (fl_orient3d + fl_orient2d on a
 *    non-degenerate projection) and the parity of exact crossings of the segment from the query
 *    to a point outside the bounding box, retried with another far point when the segment meets
 *    an edge or a plane degenerately (the mesh is a closed mod-2 cycle, so the parity does not
 *    depend on the segment);
 *  - fl_hal3_flintstone_may_contain gives 1 for the corners of every original triangle (and
 *    its rounded centroid when that lies exactly on it) at its leaf and every ancestor;
 *  - fl_hal3_approximate_level / _error: every original vertex lies within the certified error of
 *    the approximation (long-double brute-force distance); the finest level is the mesh;
 *  - fl_hal3_intersect == all pairs tested with fl_triangles_intersect (src/mesh, exact). */
#include "fuzz_common.h"
#include "mesh/intersect.h"
#include "hal/hal3_oracle.h"
#include "sweep/sweep_oracle.h"

#define H3_V 14
#define H3_T 24

static const double *h3_v(const fl_mesh *m, size_t t, int k)
{
    return m->xyz + 3 * (size_t)m->tri[3 * t + (size_t)k];
}

/* Crossings of segment x-o with the triangles; -1 when some contact is degenerate. */
static int h3_crossings(const fl_mesh *m, const double *x, const double *o)
{
    int parity = 0;
    for (size_t t = 0; t < m->triangle_count; t++) {
        const double *a = h3_v(m, t, 0), *b = h3_v(m, t, 1), *c = h3_v(m, t, 2);
        int s1 = fl_orient3d(a, b, c, x), s2 = fl_orient3d(a, b, c, o);
        if (s2 == 0) return -1;
        if (s1 == 0 || s1 == s2) continue; /* x is off the triangle (tested before) */
        int e1 = fl_orient3d(x, o, a, b), e2 = fl_orient3d(x, o, b, c);
        int e3 = fl_orient3d(x, o, c, a);
        if (e1 == 0 || e2 == 0 || e3 == 0) {
            if ((e1 >= 0 && e2 >= 0 && e3 >= 0) || (e1 <= 0 && e2 <= 0 && e3 <= 0)) return -1;
            continue;
        }
        parity ^= e1 == e2 && e2 == e3;
    }
    return parity;
}

static int h3_brute_inside(const fl_mesh *m, const double *x, double far)
{
    for (size_t t = 0; t < m->triangle_count; t++)
        if (hal3_oracle_on_triangle(h3_v(m, t, 0), h3_v(m, t, 1), h3_v(m, t, 2), x))
            return FL_HAL3_BOUNDARY;
    static const double dir[8][3] = {{1, 0.377, 0.719},   {-0.531, 1, 0.293}, {0.613, -0.457, 1},
                                     {-1, -0.211, 0.871}, {0.143, -1, -0.659}, {0.91, 0.37, -1},
                                     {-0.77, 0.59, -1},   {1, -0.93, -0.31}};
    for (int k = 0; k < 8; k++) {
        double o[3] = {far * dir[k][0], far * dir[k][1], far * dir[k][2]};
        int p = h3_crossings(m, x, o);
        if (p >= 0) return p ? FL_HAL3_INSIDE : FL_HAL3_OUTSIDE;
    }
    return -1; /* undecided: skip */
}

static int h3_mesh_bad(const fl_mesh *m)
{
    for (size_t i = 0; i < 3 * m->vertex_count; i++)
        if (!(fabs(m->xyz[i]) <= 1e150)) return 1; /* NaN/Inf or beyond the documented range */
    fl_mesh_check_options co = {.skip_self_intersections = 1};
    fl_mesh_report rep;
    fl_error err;
    if (fl_mesh_check(m, &co, &rep, &err) != FL_OK) return 1;
    int bad = !rep.closed || !rep.manifold || !rep.oriented || rep.degenerate_faces ||
              rep.components != 1 || rep.genus != 0 || rep.unreferenced_vertices;
    fl_mesh_report_free(&rep);
    return bad;
}

static ld h3_dist(const fl_mesh *m, const double *p)
{
    ld best = INFINITY;
    for (size_t t = 0; t < m->triangle_count; t++) {
        ld d = oracle_mesh_element(m->xyz, m->tri, t, p);
        if (d < best) best = d;
    }
    return best;
}

/* Every original vertex within `error` of the approximation. */
static void h3_check_approx(const fl_mesh *orig, const fl_mesh *ap, double error, double scale,
                            const char *what)
{
    FZ_ASSERT(ap->triangle_count > 0 && error >= 0 && isfinite(error), "%s: empty / bad error",
              what);
    for (size_t i = 0; i < orig->vertex_count; i++) {
        ld d = h3_dist(ap, orig->xyz + 3 * i);
        FZ_ASSERT(d <= (ld)error * (1 + 1e-9) + 1e-12 * scale + 1e-300,
                  "%s: vertex %zu is %.17Lg from the approximation, certified %.17g", what, i, d,
                  error);
    }
}

static void h3_check_tree(const fl_hal3 *h, const fl_mesh *m, double scale)
{
    for (size_t n = 0; n < h->node_count; n++) {
        const fl_hal3_node *nd = h->nodes + n;
        if (nd->kind != FL_HAL3_LEAF) continue;
        FZ_ASSERT(nd->face < m->triangle_count, "leaf face");
        const double *v[3] = {h3_v(m, nd->face, 0), h3_v(m, nd->face, 1), h3_v(m, nd->face, 2)};
        double g[3];
        for (int k = 0; k < 3; k++) g[k] = v[0][k] / 3 + v[1][k] / 3 + v[2][k] / 3;
        for (int32_t a = (int32_t)n; a >= 0; a = h->nodes[a].parent) {
            for (int k = 0; k < 3; k++)
                FZ_ASSERT(fl_hal3_flintstone_may_contain(h, (uint32_t)a, v[k]),
                          "node %d excludes a corner of face %u", (int)a, nd->face);
            /* the rounded centroid is a point of the triangle only when exactly on it (a
             * triangle with a far vertex has its rounded centroid across a corner plane) */
            FZ_ASSERT(!hal3_oracle_on_triangle(v[0], v[1], v[2], g) ||
                          fl_hal3_flintstone_may_contain(h, (uint32_t)a, g),
                      "node %d excludes the centroid of face %u", (int)a, nd->face);
        }
    }
    fl_error err;
    for (uint32_t level = 0; level <= h->depth; level++) {
        fl_mesh ap;
        double error = -1;
        fl_status st = fl_hal3_approximate_level(h, level, &ap, &error, &err);
        fz_check_status(st, &err, "fl_hal3_approximate_level");
        FZ_ASSERT(st == FL_OK, "approximate_level %u: %s", level, err.message);
        h3_check_approx(m, &ap, error, scale, "level");
        if (level == h->depth)
            FZ_ASSERT(ap.triangle_count == m->triangle_count && error == 0, "finest != mesh");
        fl_mesh_free(&ap);
    }
    double want = scale * 0.1, error = -1;
    uint32_t lev = 0;
    fl_mesh ap;
    fl_status st = fl_hal3_approximate_error(h, want, &ap, &error, &lev, &err);
    FZ_ASSERT(st == FL_OK, "approximate_error: %s", err.message);
    FZ_ASSERT(error <= want, "adaptive error %.17g > %.17g", error, want);
    h3_check_approx(m, &ap, error, scale, "adaptive");
    fl_mesh_free(&ap);
}

static int cmp_pair(const void *x, const void *y)
{
    const uint32_t *a = x, *b = y;
    return a[0] != b[0] ? (a[0] < b[0] ? -1 : 1) : (a[1] < b[1] ? -1 : a[1] > b[1]);
}

static void h3_check_intersect(const fl_hal3 *ha, const fl_hal3 *hb)
{
    const fl_mesh *a = &ha->mesh, *b = &hb->mesh;
    uint32_t brute[2 * H3_T * H3_T];
    size_t nb = 0;
    for (size_t i = 0; i < a->triangle_count; i++)
        for (size_t j = 0; j < b->triangle_count; j++)
            if (fl_triangles_intersect(h3_v(a, i, 0), h3_v(a, i, 1), h3_v(a, i, 2), h3_v(b, j, 0),
                                       h3_v(b, j, 1), h3_v(b, j, 2)))
                brute[2 * nb] = (uint32_t)i, brute[2 * nb + 1] = (uint32_t)j, nb++;
    fl_hal3_pairs p, first;
    fl_error err;
    fl_status st = fl_hal3_intersect(ha, hb, 0, &p, &err);
    FZ_ASSERT(st == FL_OK, "intersect: %s", err.message);
    FZ_ASSERT(p.count == nb, "intersect: %zu pairs, brute force %zu", p.count, nb);
    if (p.count) qsort(p.pairs, p.count, 2 * sizeof(uint32_t), cmp_pair);
    for (size_t k = 0; k < nb; k++)
        FZ_ASSERT(p.pairs[2 * k] == brute[2 * k] && p.pairs[2 * k + 1] == brute[2 * k + 1],
                  "intersect: pair %zu differs", k);
    st = fl_hal3_intersect(ha, hb, 1, &first, &err);
    FZ_ASSERT(st == FL_OK && first.count == (nb ? 1u : 0u), "first_only count %zu", first.count);
    fl_hal3_pairs_free(&first);
    fl_hal3_pairs_free(&p);
}

static int h3_build(fz_in *in, int mutate, double *xyz, uint32_t *tri, fl_mesh *m, fl_hal3 *h,
                    double *scale)
{
    size_t nv, nt;
    fz_closed_mesh(in, mutate, xyz, tri, &nv, &nt);
    *m = (fl_mesh){nv, xyz, nt, tri};
    int bad = h3_mesh_bad(m);
    *scale = 0;
    for (size_t i = 0; i < 3 * nv; i++) *scale = fmax(*scale, fabs(xyz[i]));
    uint8_t ob = fz_byte(in);
    fl_hal3_options o = {(ob & 3) * 0.3, NULL, NULL}; /* 0 (= pi/4), 0.3, 0.6, 0.9 radians */
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_hal3_build(m, &o, h, &err);
    fz_check_status(st, &err, "fl_hal3_build");
    if (bad) {
        FZ_ASSERT(st == FL_ERR_INPUT, "bad mesh gave %d: %s", (int)st, err.message);
        FZ_ASSERT(h->nodes == NULL && h->node_count == 0, "*out not zeroed");
        return 0;
    }
    FZ_ASSERT(st == FL_OK || st == FL_ERR_ALGORITHM, "valid mesh failed (%d): %s", (int)st,
              err.message);
    if (st != FL_OK) FZ_ASSERT(h->nodes == NULL, "*out not zeroed");
    return st == FL_OK;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    uint8_t head = fz_byte(&in);
    double xyz[3 * H3_V], xyz2[3 * H3_V], scale, scale2;
    uint32_t tri[3 * H3_T], tri2[3 * H3_T];
    fl_mesh m, m2;
    fl_hal3 h, h2;
    if (!h3_build(&in, head & 1, xyz, tri, &m, &h, &scale)) return 0;
    if (head & 2) h3_check_tree(&h, &m, scale);
    /* Queries: decoded points at the mesh's scale, vertices, edge midpoints, centroids. */
    double q[3 * 8];
    size_t nq = fz_byte(&in) % 9;
    double unit = scale > 0 ? scale / 4 : 1;
    for (size_t k = 0; k < nq; k++) {
        uint8_t sel = fz_byte(&in);
        size_t t = (size_t)(sel >> 2) % m.triangle_count;
        const double *a = h3_v(&m, t, 0), *b = h3_v(&m, t, 1), *c = h3_v(&m, t, 2);
        for (int x = 0; x < 3; x++) {
            switch (sel & 3) {
            case 0: q[3 * k + x] = fz_coord(&in) * unit; break;
            case 1: q[3 * k + x] = a[x]; break;
            case 2: q[3 * k + x] = a[x] / 2 + b[x] / 2; break;
            default: q[3 * k + x] = a[x] / 3 + b[x] / 3 + c[x] / 3; break;
            }
        }
    }
    int qbad = 0;
    for (size_t i = 0; i < 3 * nq; i++) qbad |= !isfinite(q[i]);
    uint8_t where[8];
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_hal3_contains(&h, q, nq, where, &err);
    fz_check_status(st, &err, "fl_hal3_contains");
    if (qbad) {
        FZ_ASSERT(st == FL_ERR_INPUT, "NaN query gave %d", (int)st);
    } else {
        FZ_ASSERT(st == FL_OK, "contains failed: %s", err.message);
        double far = 4 * scale + 8;
        for (size_t i = 0; i < 3 * nq; i++) far = fmax(far, 4 * fabs(q[i]));
        for (size_t k = 0; k < nq; k++) {
            int b = isfinite(far) ? h3_brute_inside(&m, q + 3 * k, far) : -1;
            FZ_ASSERT(b < 0 || where[k] == b, "query %zu (%.17g %.17g %.17g): hal3 %d, brute %d",
                      k, q[3 * k], q[3 * k + 1], q[3 * k + 2], where[k], b);
        }
    }
    if ((head & 4) && h3_build(&in, 0, xyz2, tri2, &m2, &h2, &scale2)) {
        h3_check_intersect(&h, &h2);
        fl_hal3_free(&h2);
    }
    fl_hal3_free(&h);
    return 0;
}
