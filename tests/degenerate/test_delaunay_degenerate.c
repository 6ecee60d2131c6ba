/* Degenerate inputs for the Delaunay (2D, 3D) and regular (3D) triangulations. Each case states
 * its expected outcome: a specific status and message fragment, or a triangulation that the
 * exact verifier accepts and whose size matches the count Euler's formula predicts (2D:
 * T = 2n - h - 2 with h the points on the hull boundary; 3D with every point on the hull:
 * hull faces = 2n - 4). */
#include "degen.h"

typedef struct dt2_case {
    const char *name;
    size_t n;
    double xy[2 * 8];
    fl_status status;
    const char *message; /* fragment of the error message */
} dt2_case;

static const double NaN_ = NAN; /* not constant-folded into the table initialisers */

static void test_dt2_failures(void)
{
    dt2_case cases[] = {
        {"empty", 0, {0}, FL_ERR_INPUT, "distinct"},
        {"one point", 1, {1, 2}, FL_ERR_INPUT, "distinct"},
        {"two points", 2, {1, 2, 3, 4}, FL_ERR_INPUT, "distinct"},
        {"all duplicates", 5, {1, 1, 1, 1, 1, 1, 1, 1, 1, 1}, FL_ERR_INPUT, "distinct"},
        {"two distinct, duplicated", 4, {0, 0, 1, 1, 0, 0, 1, 1}, FL_ERR_INPUT, "distinct"},
        {"collinear", 5, {0, 0, 1, 1, 2, 2, 3, 3, -7, -7}, FL_ERR_ALGORITHM, "collinear"},
        {"collinear, huge", 3, {-1e300, 1e300, 0, 0, 1e300, -1e300}, FL_ERR_ALGORITHM,
         "collinear"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        fl_dt2 dt;
        fl_error err;
        fl_status st = fl_dt2_build(cases[i].xy, cases[i].n, NULL, &dt, &err);
        fprintf(stderr, "  dt2 %s: %s\n", cases[i].name, err.message);
        CHECK_FAILS(st, &err, cases[i].status, cases[i].message);
        CHECK(dt.triangle_count == 0 && dt.tri == NULL); /* zeroed on failure */
    }
    double bad[6] = {0, 0, 1, 0, 0, 1};
    for (int k = 0; k < 3; k++) {
        bad[3] = k == 0 ? NaN_ : k == 1 ? INFINITY : -INFINITY;
        fl_dt2 dt;
        fl_error err;
        CHECK_FAILS(fl_dt2_build(bad, 3, NULL, &dt, &err), &err, FL_ERR_INPUT, "point 1");
    }
}

/* Builds, verifies with fl_dt2_verify and checks T = 2u - h - 2 (u distinct points). */
static void expect_dt2(const char *name, const double *xy, size_t n, size_t hull_points)
{
    fl_dt2 dt;
    fl_error err;
    fl_status st = fl_dt2_build(xy, n, NULL, &dt, &err);
    CHECK_MSG(st == FL_OK, "%s: %s", name, err.message);
    if (st != FL_OK) return;
    CHECK_MSG(fl_dt2_verify(xy, &dt, &err) == FL_OK, "%s: %s", name, err.message);
    CHECK_MSG(dt.hull_count == hull_points, "%s: hull %zu, expected %zu", name, dt.hull_count,
              hull_points);
    CHECK_MSG(dt.triangle_count == 2 * dt.unique_count - hull_points - 2,
              "%s: %zu triangles for %zu points", name, dt.triangle_count, dt.unique_count);
    fl_dt2_free(&dt);
}

static void test_dt2_degenerate_sets(void)
{
    double xy[2 * 400];
    static const double scales[] = {1, 0x1p-1000, 0x1p+990, 1e-300, 1e300 / 8};
    for (size_t s = 0; s < sizeof scales / sizeof *scales; s++) {
        char name[64];
        size_t n = grid2(xy, 8, scales[s]);
        snprintf(name, sizeof name, "8x8 grid, scale %g", scales[s]);
        expect_dt2(name, xy, n, 28); /* every cell cocircular; 28 boundary points */
        n = circle12(xy, scales[s]);
        snprintf(name, sizeof name, "12 cocircular, scale %g", scales[s]);
        expect_dt2(name, xy, n, 12);
    }
    /* Duplicates of every grid point: merged, same triangulation size. */
    size_t n = grid2(xy, 6, 1);
    memcpy(xy + 2 * n, xy, 2 * n * sizeof(double));
    expect_dt2("6x6 grid twice", xy, 2 * n, 20);
    /* Mixed scales: a 1e-300 cluster at the origin and three points near 1e300. */
    double mixed[] = {0, 0, 1e-300, 0, 0, 1e-300, 1e-300, 1e-300, 1e300, 0, 0, 1e300, -1e300,
                      -1e300};
    expect_dt2("mixed 1e-300 / 1e300", mixed, 7, 3);
    /* Collinear points plus one off the line: a fan, all line points on the hull. */
    double fan[] = {0, 0, 1, 0, 2, 0, 3, 0, 4, 0, 2, 1e-200};
    expect_dt2("collinear + one near the line", fan, 6, 6);
    /* -0.0 and +0.0 are the same point. */
    double zeros[] = {0.0, 0.0, -0.0, -0.0, 1, 0, 0, 1};
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(zeros, 4, NULL, &dt, &err), FL_OK, &err);
    CHECK_EQ_INT(dt.unique_count, 3);
    CHECK_EQ_INT(dt.duplicate_of[1], 0);
    fl_dt2_free(&dt);
}

static void test_dt3_failures(void)
{
    struct {
        const char *name;
        size_t n;
        double xyz[3 * 6];
        fl_status status;
        const char *message;
    } cases[] = {
        {"empty", 0, {0}, FL_ERR_INPUT, "distinct"},
        {"one point", 1, {1, 2, 3}, FL_ERR_INPUT, "distinct"},
        {"two points", 2, {1, 2, 3, 4, 5, 6}, FL_ERR_INPUT, "distinct"},
        {"three points", 3, {0, 0, 0, 1, 0, 0, 0, 1, 0}, FL_ERR_INPUT, "distinct"},
        {"all duplicates", 5, {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}, FL_ERR_INPUT,
         "distinct"},
        {"collinear", 5, {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, -1, -1, -1}, FL_ERR_ALGORITHM,
         "collinear"},
        {"coplanar", 5, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 5, 7, 0}, FL_ERR_ALGORITHM,
         "coplanar"},
        {"coplanar, tilted and huge", 4, {0, 0, 0, 1e300, 1e300, 1e300, 1e300, 0, 0, 0, 1e300,
                                          1e300}, FL_ERR_ALGORITHM, "coplanar"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        fl_dt3 dt;
        fl_error err;
        fl_status st = fl_dt3_build(cases[i].xyz, cases[i].n, NULL, &dt, &err);
        fprintf(stderr, "  dt3 %s: %s\n", cases[i].name, err.message);
        CHECK_FAILS(st, &err, cases[i].status, cases[i].message);
        CHECK(dt.tet_count == 0 && dt.tet == NULL);
        /* The same centres as balls of weight 0 fail the same way. */
        double xyzw[4 * 6];
        for (size_t k = 0; k < cases[i].n; k++) {
            memcpy(xyzw + 4 * k, cases[i].xyz + 3 * k, 3 * sizeof(double));
            xyzw[4 * k + 3] = 0;
        }
        fl_rt3 rt;
        st = fl_rt3_build(xyzw, cases[i].n, NULL, &rt, &err);
        CHECK_FAILS(st, &err, cases[i].status, cases[i].message);
    }
    double bad[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    bad[7] = NaN_;
    fl_dt3 dt;
    fl_error err;
    CHECK_FAILS(fl_dt3_build(bad, 4, NULL, &dt, &err), &err, FL_ERR_INPUT, "NaN");
    double badw[16] = {0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    badw[15] = INFINITY; /* an infinite weight */
    fl_rt3 rt;
    CHECK_FAILS(fl_rt3_build(badw, 4, NULL, &rt, &err), &err, FL_ERR_INPUT, "infinite");
}

/* Builds, verifies; when every distinct point is a hull vertex, checks F = 2n - 4. */
static void expect_dt3(const char *name, const double *xyz, size_t n, int all_on_hull)
{
    fl_dt3 dt;
    fl_error err;
    fl_status st = fl_dt3_build(xyz, n, NULL, &dt, &err);
    CHECK_MSG(st == FL_OK, "%s: %s", name, err.message);
    if (st != FL_OK) return;
    CHECK_MSG(fl_dt3_verify(xyz, &dt, &err) == FL_OK, "%s: %s", name, err.message);
    if (all_on_hull)
        CHECK_MSG(dt.hull_face_count == 2 * dt.unique_count - 4, "%s: %zu hull faces, %zu points",
                  name, dt.hull_face_count, dt.unique_count);
    fl_dt3_free(&dt);
}

static void test_dt3_degenerate_sets(void)
{
    double xyz[3 * 200];
    static const double scales[] = {1, 0x1p-1000, 0x1p+990, 1e-300};
    for (size_t s = 0; s < sizeof scales / sizeof *scales; s++) {
        char name[64];
        size_t n = grid3(xyz, 4, scales[s]);
        snprintf(name, sizeof name, "4x4x4 grid, scale %g", scales[s]);
        expect_dt3(name, xyz, n, 0);
        n = sphere30(xyz, scales[s]);
        snprintf(name, sizeof name, "30 cospherical, scale %g", scales[s]);
        expect_dt3(name, xyz, n, 1);
    }
    size_t n = grid3(xyz, 3, 1);
    memcpy(xyz + 3 * n, xyz, 3 * n * sizeof(double));
    expect_dt3("3x3x3 grid twice", xyz, 2 * n, 0);
    double mixed[] = {0, 0, 0, 1e-300, 0, 0, 0, 1e-300, 0, 0, 0, 1e-300,
                      1e300, 0, 0, 0, 1e300, 0, 0, 0, 1e300, -1e300, -1e300, -1e300};
    expect_dt3("mixed 1e-300 / 1e300", mixed, 8, 0);
}

/* Sum of the tetrahedra's volumes (floating point; exact here: small integer coordinates). */
static double tet_volume(const double *p, size_t stride, const uint32_t *tet, size_t count)
{
    double vol = 0;
    for (size_t t = 0; t < count; t++) {
        const double *a = p + stride * tet[4 * t], *b = p + stride * tet[4 * t + 1];
        const double *c = p + stride * tet[4 * t + 2], *d = p + stride * tet[4 * t + 3];
        double u[3], v[3], w[3];
        for (int k = 0; k < 3; k++) u[k] = b[k] - a[k], v[k] = c[k] - a[k], w[k] = d[k] - a[k];
        vol += fabs(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                    u[2] * (v[0] * w[1] - v[1] * w[0])) / 6;
    }
    return vol;
}

/* Regular triangulation: equal weights tile the hull of the centres like Delaunay does; a ball
 * at the centre of a much heavier one is hidden; a duplicate ball is merged. */
static void test_rt3_degenerate_sets(void)
{
    double xyz[3 * 64], xyzw[4 * 66];
    size_t n = grid3(xyz, 4, 1);
    for (size_t i = 0; i < n; i++) {
        memcpy(xyzw + 4 * i, xyz + 3 * i, 3 * sizeof(double));
        xyzw[4 * i + 3] = 0.25;
    }
    fl_dt3 dt;
    fl_rt3 rt;
    fl_error err;
    CHECK_STATUS(fl_dt3_build(xyz, n, NULL, &dt, &err), FL_OK, &err);
    CHECK_STATUS(fl_rt3_build(xyzw, n, NULL, &rt, &err), FL_OK, &err);
    CHECK_STATUS(fl_rt3_verify(xyzw, &rt, &err), FL_OK, &err);
    /* Both tile the 3x3x3 cube: volume 27 (a grid cube may be cut into 5 or 6 tetrahedra, so
     * the counts need not agree). */
    CHECK_NEAR(tet_volume(xyz, 3, dt.tet, dt.tet_count), 27.0, 1e-9);
    CHECK_NEAR(tet_volume(xyzw, 4, rt.tet, rt.tet_count), 27.0, 1e-9);
    CHECK_EQ_INT(rt.hidden_count, 0);
    fl_rt3_free(&rt);
    fl_dt3_free(&dt);
    /* Ball 64: centre of the grid cell (1.5,1.5,1.5) with a tiny weight is hidden by the
     * neighbours (power distance); ball 65 repeats ball 0. */
    double extra[8] = {1.5, 1.5, 1.5, -10, 0, 0, 0, 0.25};
    memcpy(xyzw + 4 * n, extra, sizeof extra);
    CHECK_STATUS(fl_rt3_build(xyzw, n + 2, NULL, &rt, &err), FL_OK, &err);
    CHECK_STATUS(fl_rt3_verify(xyzw, &rt, &err), FL_OK, &err);
    CHECK_EQ_INT(rt.hidden_count, 1);
    if (rt.hidden_count == 1) CHECK_EQ_INT(rt.hidden[0], n);
    CHECK_EQ_INT(rt.duplicate_of[n + 1], 0);
    fl_rt3_free(&rt);
}

int main(void)
{
    fl_test_case cases[] = {
        FL_TEST_CASE(test_dt2_failures),        FL_TEST_CASE(test_dt2_degenerate_sets),
        FL_TEST_CASE(test_dt3_failures),        FL_TEST_CASE(test_dt3_degenerate_sets),
        FL_TEST_CASE(test_rt3_degenerate_sets),
    };
    return fl_test_run(cases, sizeof cases / sizeof *cases);
}
