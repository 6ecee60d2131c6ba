/* Degenerate inputs for the capabilities that take a mesh or a polygon rather than points:
 * HAL 3D (build + inclusion), the Hausdorff distance, G1 curves and surfaces, and the skin
 * (function, mesher, ε-approximation). Every case states its outcome: a specific error and a
 * message fragment, or a result checked by an independent fact (a vertex's inclusion answer,
 * a distance known in closed form, interpolation of the input, a sphere's radius, an Euler
 * characteristic counted on the output). */
#include <stdlib.h>

#include "degen.h"

/* ---- small closed meshes ---------------------------------------------------------------- */

static const uint32_t TET_T[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

static void tet_vertices(double *v, double s)
{
    static const double u[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int i = 0; i < 12; i++) v[i] = u[i] * s;
}

/* Octahedron |x|+|y|+|z| = s, outward counter-clockwise. */
static const uint32_t OCT_T[] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

static void oct_vertices(double *v, double s)
{
    static const double u[] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    for (int i = 0; i < 18; i++) v[i] = u[i] * s;
}

/* A 4 x 3 torus (R = 2, r = 1): 12 vertices, 24 triangles, genus 1. */
static void torus43(double *v, uint32_t *t)
{
    const int nu = 4, nv = 3;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double a = 6.283185307179586 * i / nu, b = 6.283185307179586 * j / nv;
            double *p = v + 3 * (i * nv + j);
            p[0] = (2 + cos(b)) * cos(a), p[1] = (2 + cos(b)) * sin(a), p[2] = sin(b);
        }
    int k = 0;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            uint32_t a = (uint32_t)(i * nv + j), b = (uint32_t)(((i + 1) % nu) * nv + j);
            uint32_t c = (uint32_t)(((i + 1) % nu) * nv + (j + 1) % nv);
            uint32_t d = (uint32_t)(i * nv + (j + 1) % nv);
            uint32_t q[6] = {a, b, c, a, c, d};
            memcpy(t + 6 * k++, q, sizeof q);
        }
}

static long long euler(const fl_mesh *m)
{
    fl_mesh_report rep;
    fl_error err;
    if (fl_mesh_check(m, NULL, &rep, &err) != FL_OK) return 1000;
    long long chi = (long long)rep.vertices - (long long)rep.edges + (long long)rep.faces;
    fl_mesh_report_free(&rep);
    return chi;
}

/* ---- HAL 3D -------------------------------------------------------------------------------- */

static void expect_hal3_rejects(const char *name, const fl_mesh *m, const char *needle)
{
    fl_hal3 hal;
    fl_error err;
    fl_status st = fl_hal3_build(m, NULL, &hal, &err);
    CHECK_MSG(st == FL_ERR_INPUT, "%s: status %d (%s)", name, (int)st, err.message);
    CHECK_MSG(strstr(err.message, needle) != NULL, "%s: '%s' lacks '%s'", name, err.message,
              needle);
    if (st == FL_OK) fl_hal3_free(&hal);
}

static void test_hal3_degenerate(void)
{
    double v[36];
    uint32_t t[72];
    tet_vertices(v, 1);
    fl_mesh empty = {4, v, 0, (uint32_t *)TET_T};
    expect_hal3_rejects("no triangles", &empty, "");
    fl_mesh too_few = {4, v, 3, (uint32_t *)TET_T};
    expect_hal3_rejects("3 triangles", &too_few, "at least 4");
    double ov[18];
    oct_vertices(ov, 1);
    fl_mesh open = {6, ov, 7, (uint32_t *)OCT_T};
    expect_hal3_rejects("open (a face missing)", &open, "boundary edges");
    memcpy(t, TET_T, sizeof TET_T);
    uint32_t s = t[0];
    t[0] = t[1], t[1] = s; /* one face turned over */
    fl_mesh flipped = {4, v, 4, t};
    expect_hal3_rejects("inconsistently oriented", &flipped, "orient");
    double v2[24];
    tet_vertices(v2, 1);
    tet_vertices(v2 + 12, 1);
    for (int i = 12; i < 24; i += 3) v2[i] += 5;
    uint32_t t2[24];
    memcpy(t2, TET_T, sizeof TET_T);
    for (int i = 0; i < 12; i++) t2[12 + i] = TET_T[i] + 4;
    fl_mesh two = {8, v2, 8, t2};
    expect_hal3_rejects("two components", &two, "component");
    torus43(v, t);
    fl_mesh torus = {12, v, 24, t};
    expect_hal3_rejects("genus 1", &torus, "genus");
    tet_vertices(v, 1);
    v[11] = 0; /* the apex in the base plane: four degenerate (flat) faces */
    fl_mesh flat = {4, v, 4, (uint32_t *)TET_T};
    expect_hal3_rejects("flat tetrahedron", &flat, "");
    tet_vertices(v, 1);
    v[4] = NAN;
    fl_mesh nan = {4, v, 4, (uint32_t *)TET_T};
    expect_hal3_rejects("NaN coordinate", &nan, "");
    tet_vertices(v, 1e200);
    fl_mesh huge = {4, v, 4, (uint32_t *)TET_T};
    expect_hal3_rejects("coordinates beyond 1e150", &huge, "");

    /* Accepted at extreme (but allowed) scales: inclusion of the centroid, a vertex, a point
     * outside; every level's certified error covers the vertices (they stay on the mesh). */
    const double scales[] = {1e-140, 1, 1e140};
    for (int k = 0; k < 3; k++) {
        oct_vertices(v, scales[k]);
        fl_mesh oct = {6, v, 8, (uint32_t *)OCT_T};
        fl_hal3 hal;
        fl_error err;
        fl_status st = fl_hal3_build(&oct, NULL, &hal, &err);
        CHECK_MSG(st == FL_OK, "octahedron at %g: %s", scales[k], err.message);
        if (st != FL_OK) continue;
        double q[9] = {0.1 * scales[k], 0.2 * scales[k], -0.1 * scales[k], v[0], v[1], v[2],
                       scales[k], scales[k], scales[k]};
        uint8_t w[3];
        CHECK_STATUS(fl_hal3_contains(&hal, q, 3, w, &err), FL_OK, &err);
        CHECK_EQ_INT(w[0], FL_HAL3_INSIDE);
        CHECK_EQ_INT(w[1], FL_HAL3_BOUNDARY);
        CHECK_EQ_INT(w[2], FL_HAL3_OUTSIDE);
        double qn[3] = {NAN, 0, 0};
        CHECK_STATUS(fl_hal3_contains(&hal, qn, 1, w, &err), FL_ERR_INPUT, &err);
        fl_hal3_free(&hal);
    }
}

/* ---- Hausdorff ----------------------------------------------------------------------------- */

static void expect_interval(const char *name, const fl_hausdorff_result *r, double truth)
{
    CHECK_MSG(r->hausdorff[0] <= truth * (1 + 1e-12) && truth <= r->hausdorff[1] * (1 + 1e-12),
              "%s: [%.17g, %.17g] misses %.17g", name, r->hausdorff[0], r->hausdorff[1], truth);
}

static void test_hausdorff_degenerate(void)
{
    fl_error err;
    fl_hausdorff_result r;
    double v[12];
    tet_vertices(v, 1);
    fl_mesh tet = {4, v, 4, (uint32_t *)TET_T};
    fl_mesh none = {4, v, 0, (uint32_t *)TET_T};
    CHECK_FAILS(fl_hausdorff_meshes(&tet, &none, NULL, &r, &err), &err, FL_ERR_INPUT, "");
    uint32_t bad[] = {0, 1, 7};
    fl_mesh out_of_range = {4, v, 1, bad};
    CHECK_FAILS(fl_hausdorff_meshes(&tet, &out_of_range, NULL, &r, &err), &err, FL_ERR_INPUT,
                "");
    double vn[12];
    tet_vertices(vn, 1);
    vn[5] = INFINITY;
    fl_mesh inf = {4, vn, 4, (uint32_t *)TET_T};
    CHECK_FAILS(fl_hausdorff_meshes(&tet, &inf, NULL, &r, &err), &err, FL_ERR_INPUT, "");
    double one[] = {0, 0};
    double seg[] = {0, 0, 1, 0};
    CHECK_FAILS(fl_hausdorff_polylines(one, 1, 0, seg, 2, 0, 2, NULL, &r, &err), &err,
                FL_ERR_INPUT, "");
    CHECK_STATUS(fl_hausdorff_polylines(seg, 2, 0, seg, 2, 0, 4, NULL, &r, &err), FL_ERR_USAGE,
                 &err);

    /* The same mesh twice: distance 0. */
    fl_hausdorff_options opt = {0};
    opt.precision = 1e-9;
    CHECK_STATUS(fl_hausdorff_meshes(&tet, &tet, &opt, &r, &err), FL_OK, &err);
    CHECK(r.hausdorff[0] == 0 && r.hausdorff[1] <= 1e-9);
    fl_hausdorff_result_free(&r);

    /* Meshes of degenerate triangles only: three collinear points a triangle, two parallel
     * "segments" at distance 1 (closed form: 1), at three scales; and two parallel segments
     * as 2D polylines at distance d (closed form: d). */
    const double scales[] = {1e-100, 1, 1e100};
    for (int k = 0; k < 3; k++) {
        double s = scales[k];
        double va[] = {0, 0, 0, s, 0, 0, 2 * s, 0, 0}, vb[] = {0, s, 0, s, s, 0, 2 * s, s, 0};
        uint32_t tt[] = {0, 1, 2, 2, 1, 0};
        fl_mesh a = {3, va, 2, tt}, b = {3, vb, 2, tt};
        opt.precision = 1e-6 * s;
        CHECK_STATUS(fl_hausdorff_meshes(&a, &b, &opt, &r, &err), FL_OK, &err);
        expect_interval("collinear triangles", &r, s);
        fl_hausdorff_result_free(&r);
        double pa[] = {0, 0, 3 * s, 0}, pb[] = {0, 0.5 * s, 3 * s, 0.5 * s};
        CHECK_STATUS(fl_hausdorff_polylines(pa, 2, 0, pb, 2, 0, 2, &opt, &r, &err), FL_OK, &err);
        expect_interval("parallel segments", &r, 0.5 * s);
        fl_hausdorff_result_free(&r);
    }
    /* Repeated points in a polyline and a duplicated triangle change nothing. */
    double rep[] = {0, 0, 0, 0, 3, 0, 3, 0}, pb[] = {0, 2, 3, 2};
    opt.precision = 1e-9;
    CHECK_STATUS(fl_hausdorff_polylines(rep, 4, 0, pb, 2, 0, 2, &opt, &r, &err), FL_OK, &err);
    expect_interval("repeated polyline points", &r, 2);
    fl_hausdorff_result_free(&r);
}

/* ---- G1 curves and surfaces ------------------------------------------------------------------ */

static void expect_curve(const char *name, double *xy, size_t n, fl_status expected)
{
    size_t rs[2] = {0, n}, ps[2] = {0, 1};
    fl_polygon p = {n, xy, 1, rs, 1, ps};
    fl_g1_curve c;
    fl_error err;
    fl_status st = fl_g1_curve_build(&p, NULL, &c, &err);
    CHECK_MSG(st == expected, "%s: status %d, expected %d (%s)", name, (int)st, (int)expected,
              err.message);
    if (st != FL_OK) {
        CHECK_MSG(err.message[0] != '\0', "%s: no message", name);
        return;
    }
    /* Interpolation: segment i starts at vertex i and ends at vertex i + 1; finite controls. */
    for (size_t i = 0; i < n; i++) {
        const double *q = c.ctrl + 8 * i, *a = xy + 2 * i, *b = xy + 2 * ((i + 1) % n);
        CHECK_MSG(q[0] == a[0] && q[1] == a[1] && q[6] == b[0] && q[7] == b[1],
                  "%s: segment %zu does not join its vertices", name, i);
        for (int k = 0; k < 8; k++) CHECK_MSG(isfinite(q[k]), "%s: non-finite control", name);
    }
    fl_g1_curve_free(&c);
}

static void test_g1_curve_degenerate(void)
{
    double two[] = {0, 0, 1, 0};
    expect_curve("2 vertices", two, 2, FL_ERR_INPUT);
    double dup[] = {0, 0, 1, 0, 1, 0, 0, 1};
    expect_curve("consecutive duplicates", dup, 4, FL_ERR_INPUT);
    double spike[] = {0, 0, 2, 0, 1, 0, 1, 1};
    expect_curve("180-degree turn", spike, 4, FL_ERR_INPUT);
    double nan[] = {0, 0, 1, NAN, 0, 1};
    expect_curve("NaN", nan, 3, FL_ERR_INPUT);
    double huge[] = {0, 0, 1e200, 0, 0, 1e200};
    expect_curve("beyond 1e150", huge, 3, FL_ERR_INPUT);
    double collinear[] = {0, 0, 1, 0, 2, 0, 2, 2, 0, 2};
    expect_curve("collinear vertex on an edge", collinear, 5, FL_OK);
    const double scales[] = {1e-140, 1e140};
    for (int k = 0; k < 2; k++) {
        double sq[] = {0, 0, scales[k], 0, scales[k], scales[k], 0, scales[k]};
        expect_curve("square at extreme scale", sq, 4, FL_OK);
    }
}

static void expect_surface(const char *name, const fl_mesh *m, fl_status expected)
{
    fl_g1_surface s;
    fl_error err;
    fl_g1_surface_options opt = {0};
    fl_status st = fl_g1_surface_build(m, &opt, &s, &err);
    CHECK_MSG(st == expected, "%s: status %d, expected %d (%s)", name, (int)st, (int)expected,
              err.message);
    if (st != FL_OK) {
        CHECK_MSG(err.message[0] != '\0', "%s: no message", name);
        return;
    }
    /* Every mesh vertex is a patch corner, interpolated to 1e-12 of the mesh's size. */
    double size = 0;
    for (size_t i = 0; i < 3 * m->vertex_count; i++) size = fmax(size, fabs(m->xyz[i]));
    for (size_t p = 0; p < s.patch_count; p++)
        for (int c = 0; c < 3; c++) {
            uint32_t node = s.corner[3 * p + (size_t)c];
            if (node >= m->vertex_count) continue;
            static const int at[3] = {0, 6, 9}; /* b300, b030, b003 */
            const double *q = s.ctrl + 30 * p + 3 * at[c];
            for (int k = 0; k < 3; k++)
                CHECK_MSG(fabs(q[k] - m->xyz[3 * node + k]) <= 1e-12 * size,
                          "%s: vertex %u not interpolated", name, node);
        }
    fl_g1_surface_free(&s);
}

static void test_g1_surface_degenerate(void)
{
    double v[36];
    uint32_t t[72];
    tet_vertices(v, 1);
    fl_mesh open = {4, v, 3, (uint32_t *)TET_T};
    expect_surface("open", &open, FL_ERR_INPUT);
    memcpy(t, TET_T, sizeof TET_T);
    uint32_t s = t[3];
    t[3] = t[4], t[4] = s;
    fl_mesh flipped = {4, v, 4, t};
    expect_surface("inconsistently oriented", &flipped, FL_ERR_INPUT);
    uint32_t nm[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 1, 3};
    fl_mesh nonmanifold = {4, v, 5, nm};
    expect_surface("non-manifold edge", &nonmanifold, FL_ERR_INPUT);
    v[0] = NAN;
    fl_mesh nan = {4, v, 4, (uint32_t *)TET_T};
    expect_surface("NaN", &nan, FL_ERR_INPUT);
    const double scales[] = {1e-140, 1, 1e140};
    for (int k = 0; k < 3; k++) {
        tet_vertices(v, scales[k]);
        fl_mesh tet = {4, v, 4, (uint32_t *)TET_T};
        expect_surface("tetrahedron at an extreme scale", &tet, FL_OK);
    }
    torus43(v, t);
    fl_mesh torus = {12, v, 24, t};
    expect_surface("genus 1 (any closed manifold is accepted)", &torus, FL_OK);
}

/* ---- skin ------------------------------------------------------------------------------------ */

static void test_skin_degenerate(void)
{
    fl_error err;
    fl_skin_function *f;
    double one[] = {0, 0, 0, 1};
    CHECK_STATUS(fl_skin_function_new(one, 1, 0, &f, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_skin_function_new(one, 1, 1, &f, &err), FL_ERR_USAGE, &err);
    double neg[] = {0, 0, 0, -1, 3, 0, 0, 0};
    CHECK_FAILS(fl_skin_function_new(neg, 2, 0.5, &f, &err), &err, FL_ERR_INPUT, "positive");
    double nan[] = {0, NAN, 0, 1};
    CHECK_STATUS(fl_skin_function_new(nan, 1, 0.5, &f, &err), FL_ERR_INPUT, &err);
    double flat[4 * 12];
    for (int i = 0; i < 12; i++) /* 12 centres in the plane z = 0, more than 8 */
        flat[4 * i] = i % 4, flat[4 * i + 1] = i / 4, flat[4 * i + 2] = 0, flat[4 * i + 3] = 0.4;
    /* the regular triangulation's reason is kept in the message (fl_fail used to clear it) */
    CHECK_FAILS(fl_skin_function_new(flat, 12, 0.5, &f, &err), &err, FL_ERR_INPUT,
                "skin: all 12 distinct points are coplanar");

    /* One ball: the skin is the sphere of radius sqrt(t w) (paper §2.1), Euler 2. Two equal
     * balls (a duplicate) give the same surface; two far-apart balls two spheres, Euler 4. */
    double dup[] = {1, 2, 3, 4, 1, 2, 3, 4};
    double apart[] = {0, 0, 0, 1, 10, 0, 0, 1};
    const struct { const double *b; size_t n; long long euler; } cases[] = {
        {dup, 1, 2}, {dup, 2, 2}, {apart, 2, 4}};
    for (int c = 0; c < 3; c++) {
        fl_mesh m;
        fl_skin_options opt = {0};
        opt.t = 0.5;
        CHECK_STATUS(fl_skin_mesh(cases[c].b, cases[c].n, &opt, &m, NULL, &err), FL_OK, &err);
        CHECK_MSG(euler(&m) == cases[c].euler, "case %d: Euler %lld", c, euler(&m));
        for (size_t i = 0; i < m.vertex_count; i++) {
            const double *p = m.xyz + 3 * i, *b = cases[c].b;
            if (cases[c].b == apart && p[0] > 5) b += 4;
            double d = sqrt((p[0] - b[0]) * (p[0] - b[0]) + (p[1] - b[1]) * (p[1] - b[1]) +
                            (p[2] - b[2]) * (p[2] - b[2]));
            CHECK_NEAR(d, sqrt(0.5 * b[3]), 1e-9);
        }
        fl_mesh_free(&m);
    }

    /* The ε-approximation refuses what is not a closed oriented manifold, and bad ε. */
    double v[12];
    tet_vertices(v, 1);
    fl_mesh tet = {4, v, 4, (uint32_t *)TET_T}, open = {4, v, 3, (uint32_t *)TET_T};
    fl_skin_approx a;
    CHECK_STATUS(fl_skin_approx_build(&open, 0.5, NULL, &a, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_skin_approx_build(&tet, 0, NULL, &a, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_skin_approx_build(&tet, NAN, NULL, &a, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_skin_approx_build(&tet, -1, NULL, &a, &err), FL_ERR_INPUT, &err);
    v[2] = INFINITY;
    CHECK_STATUS(fl_skin_approx_build(&tet, 0.5, NULL, &a, &err), FL_ERR_INPUT, &err);
}

int main(void)
{
    fl_test_case cases[] = {
        FL_TEST_CASE(test_hal3_degenerate),
        FL_TEST_CASE(test_hausdorff_degenerate),
        FL_TEST_CASE(test_g1_curve_degenerate),
        FL_TEST_CASE(test_g1_surface_degenerate),
        FL_TEST_CASE(test_skin_degenerate),
    };
    return fl_test_run(cases, sizeof cases / sizeof *cases);
}
