/* Certified Hausdorff distance (Guéziec §6) on shapes whose distance is known in closed form or
 * checked by dense brute-force sampling (hausdorff_oracle.h). */
#include <stdint.h>

#include "fl_test.h"
#include "hausdorff_oracle.h"
#include "sweep/sweep_internal.h"

/* Contains x up to the rounding slack of the certificate. */
static int contains(const double *iv, double x)
{
    return iv[0] <= x + 1e-13 && x <= iv[1] + 1e-13;
}

/* Two unit squares in parallel planes at distance d, meshed differently (2 triangles against
 * an 8x8 grid): h_ab = h_ba = d exactly. */
static void test_parallel_squares_are_at_their_offset(void)
{
    const double d = 0.1;
    fl_mesh a = oracle_grid(1, 0, 0, 0), b = oracle_grid(8, 0, 0, d);
    fl_hausdorff_options o = {0};
    o.precision = 1e-6;
    o.both_directions = 1;
    fl_hausdorff_result r;
    fl_error err;
    CHECK_STATUS(fl_hausdorff_meshes(&a, &b, &o, &r, &err), FL_OK, &err);
    CHECK_MSG(contains(r.h_ab, d), "[%.17g, %.17g]", r.h_ab[0], r.h_ab[1]);
    CHECK_MSG(contains(r.h_ba, d), "[%.17g, %.17g]", r.h_ba[0], r.h_ba[1]);
    CHECK(r.h_ab[1] - r.h_ab[0] <= 1e-6 && r.h_ba[1] - r.h_ba[0] <= 1e-6);
    CHECK(!r.budget_exhausted);
    fl_hausdorff_result_free(&r);
    fl_mesh_free(&a);
    fl_mesh_free(&b);
}

/* Squares offset by (s, 0, d): the edge x = 0 of A is sqrt(s^2 + d^2) from B and no point is
 * farther (same for B's edge x = 1 + s). The maximum is on a boundary edge, reached only by
 * refining along it. */
static void test_shifted_squares_reach_the_corner_distance(void)
{
    const double s = 0.3, d = 0.2, h = sqrt(s * s + d * d);
    fl_mesh a = oracle_grid(3, 0, 0, 0), b = oracle_grid(5, s, 0, d);
    fl_hausdorff_options o = {0};
    o.precision = 1e-7;
    o.both_directions = 1;
    fl_hausdorff_result r;
    fl_error err;
    CHECK_STATUS(fl_hausdorff_meshes(&a, &b, &o, &r, &err), FL_OK, &err);
    CHECK_MSG(contains(r.h_ab, h), "[%.17g, %.17g] vs %.17g", r.h_ab[0], r.h_ab[1], h);
    CHECK_MSG(contains(r.h_ba, h), "[%.17g, %.17g] vs %.17g", r.h_ba[0], r.h_ba[1], h);
    CHECK(contains(r.hausdorff, h) && r.hausdorff[1] - r.hausdorff[0] <= 1e-7);
    fl_hausdorff_result_free(&r);
    fl_mesh_free(&a);
    fl_mesh_free(&b);
}

/* A mesh against itself: every sample is on the other shape, the interval is [0, <= eps]. */
static void test_mesh_against_itself_is_zero(void)
{
    const double t[3] = {0.1, 0.2, 0.3};
    fl_mesh a = oracle_cube(0.4, t);
    fl_hausdorff_options o = {0};
    o.relative = 1e-9;
    fl_hausdorff_result r;
    fl_error err;
    CHECK_STATUS(fl_hausdorff_meshes(&a, &a, &o, &r, &err), FL_OK, &err);
    CHECK(r.hausdorff[0] == 0);
    CHECK_MSG(r.hausdorff[1] <= r.precision, "upper %.3g", r.hausdorff[1]);
    /* No split: the vertices and one query a triangle (the element at the closest points'
     * centroid) close every triangle by the same-element bound. */
    CHECK_MSG(r.samples <= 2 * (8 + 12), "%zu samples", r.samples);
    fl_hausdorff_result_free(&r);
    fl_mesh_free(&a);
}

/* An equilateral triangle (side 1) against its three corners as a point set (degenerate
 * triangles): h(triangle, corners) = circumradius 1/sqrt(3), reached at the circumcentre;
 * h(corners, triangle) = 0. */
static void test_triangle_against_its_corners_is_the_circumradius(void)
{
    fl_mesh a = oracle_mesh_alloc(3, 1), b = oracle_mesh_alloc(3, 3);
    const double v[9] = {0, 0, 0, 1, 0, 0, 0.5, sqrt(3.0) / 2, 0};
    memcpy(a.xyz, v, sizeof v);
    memcpy(b.xyz, v, sizeof v);
    for (uint32_t i = 0; i < 3; i++) {
        a.tri[i] = i;
        b.tri[3 * i] = b.tri[3 * i + 1] = b.tri[3 * i + 2] = i;
    }
    fl_hausdorff_options o = {0};
    o.precision = 1e-6;
    fl_hausdorff_result r;
    fl_error err;
    CHECK_STATUS(fl_hausdorff_meshes(&a, &b, &o, &r, &err), FL_OK, &err);
    double R = 1 / sqrt(3.0);
    CHECK_MSG(contains(r.h_ab, R), "[%.17g, %.17g]", r.h_ab[0], r.h_ab[1]);
    CHECK(r.h_ab[1] - r.h_ab[0] <= 1e-6);
    CHECK(r.h_ba[0] == 0 && r.h_ba[1] <= 1e-6);
    CHECK(!r.where_on_b);
    CHECK_NEAR(r.where[0][0], 0.5, 1e-3); /* near the circumcentre (0.5, R/2) */
    CHECK_NEAR(r.where[0][1], R / 2, 1e-3);
    fl_hausdorff_result_free(&r);
    fl_mesh_free(&a);
    fl_mesh_free(&b);
}

/* An icosahedron subdivided and pushed to the unit sphere, n = levels of 4-splits. */
static fl_mesh icosphere(int levels)
{
    const double g = (1 + sqrt(5.0)) / 2;
    static const uint32_t f[60] = {0, 11, 5, 0, 5,  1,  0,  1,  7,  0,  7, 10, 0, 10, 11,
                                   1, 5,  9, 5, 11, 4,  11, 10, 2,  10, 7, 6,  7, 1,  8,
                                   3, 9,  4, 3, 4,  2,  3,  2,  6,  3,  6, 8,  3, 8,  9,
                                   4, 9,  5, 2, 4,  11, 6,  2,  10, 8,  6, 7,  9, 8,  1};
    const double v0[36] = {-1, g,  0,  1, g, 0,  -1, -g, 0,  1, -g, 0, 0,  -1, g,  0,  1, g,
                           0,  -1, -g, 0, 1, -g, g,  0,  -1, g, 0,  1, -g, 0,  -1, -g, 0, 1};
    fl_mesh m = oracle_mesh_alloc(12, 20);
    memcpy(m.xyz, v0, sizeof v0);
    memcpy(m.tri, f, sizeof f);
    for (int l = 0; l < levels; l++) { /* 4-split with one new vertex per half-edge */
        fl_mesh n = oracle_mesh_alloc(m.vertex_count + 3 * m.triangle_count, 4 * m.triangle_count);
        memcpy(n.xyz, m.xyz, 3 * m.vertex_count * sizeof(double));
        size_t nv = m.vertex_count;
        for (size_t t = 0; t < m.triangle_count; t++) {
            uint32_t c[3], mid[3];
            for (int k = 0; k < 3; k++)
                c[k] = m.tri[3 * t + (size_t)k];
            for (int k = 0; k < 3; k++) {
                mid[k] = (uint32_t)nv++;
                for (int x = 0; x < 3; x++)
                    n.xyz[3 * mid[k] + x] =
                        0.5 * (m.xyz[3 * c[k] + x] + m.xyz[3 * c[(k + 1) % 3] + x]);
            }
            uint32_t tt[12] = {c[0], mid[0], mid[2], c[1],   mid[1], mid[0],
                               c[2], mid[2], mid[1], mid[0], mid[1], mid[2]};
            memcpy(n.tri + 12 * t, tt, sizeof tt);
        }
        fl_mesh_free(&m);
        m = n;
    }
    for (size_t v = 0; v < m.vertex_count; v++) {
        double *p = m.xyz + 3 * v, r = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        p[0] /= r, p[1] /= r, p[2] /= r;
    }
    return m;
}

/* A convex polyhedron A inscribed in the unit sphere against B = 1.2 A: every point y of B is
 * 1.2 x for x on A, at distance 0.2 |x| <= 0.2, with equality at the vertices (no point of A
 * is outside the unit ball), so h(B, A) = 0.2; h(A, B) is smaller (A is inside B). */
static void test_sphere_against_scaled_copy(void)
{
    fl_mesh a = icosphere(2), b = icosphere(2);
    for (size_t i = 0; i < 3 * b.vertex_count; i++)
        b.xyz[i] *= 1.2;
    fl_hausdorff_options o = {0};
    o.precision = 1e-6;
    fl_hausdorff_result r;
    fl_error err;
    CHECK_STATUS(fl_hausdorff_meshes(&a, &b, &o, &r, &err), FL_OK, &err);
    CHECK_MSG(contains(r.h_ba, 0.2), "[%.17g, %.17g]", r.h_ba[0], r.h_ba[1]);
    CHECK(contains(r.hausdorff, 0.2) && r.hausdorff[1] - r.hausdorff[0] <= 1e-6);
    CHECK(r.where_on_b);
    CHECK(r.h_ab[1] < 0.2);
    oracle_check_certificate(&a, &b, &r, 4, 1);
    fl_hausdorff_result_free(&r);
    fl_mesh_free(&a);
    fl_mesh_free(&b);
}

/* A cube against the same cube rotated by 0.05 rad: compared with dense sampling. */
static void test_cube_against_rotated_cube_matches_dense_sampling(void)
{
    const double t0[3] = {0, 0, 0};
    fl_mesh a = oracle_cube(0, t0), b = oracle_cube(0.05, t0);
    fl_hausdorff_options o = {0};
    o.relative = 1e-5;
    o.both_directions = 1;
    fl_hausdorff_result r;
    fl_error err;
    CHECK_STATUS(fl_hausdorff_meshes(&a, &b, &o, &r, &err), FL_OK, &err);
    oracle_check_certificate(&a, &b, &r, 60, 1);
    CHECK(r.h_ab[1] - r.h_ab[0] <= r.precision && r.h_ba[1] - r.h_ba[0] <= r.precision);
    fl_hausdorff_result_free(&r);
    fl_mesh_free(&a);
    fl_mesh_free(&b);
}

/* Two 2D polylines: a unit square (closed) against the same square shifted by (0.1, 0) and
 * open (missing its left side): h(B, A) = 0.1 (B's points are 0.1 from A's sides at most... ),
 * h(A, B) = the left side of A to B: its midpoint (0, 0.5) is 0.5 from B (nearest: the ends
 * (0.1, 0), (0.1, 1) of B are at sqrt(0.01 + 0.25)). */
static void test_polyline_square_against_open_shifted_square(void)
{
    const double a[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    const double b[8] = {0.1, 1, 1.1, 1, 1.1, 0, 0.1, 0}; /* open: 3 sides, no left side */
    fl_hausdorff_options o = {0};
    o.precision = 1e-9;
    o.both_directions = 1;
    fl_hausdorff_result r;
    fl_error err;
    CHECK_STATUS(fl_hausdorff_polylines(a, 4, 1, b, 4, 0, 2, &o, &r, &err), FL_OK, &err);
    double hab = sqrt(0.01 + 0.25);
    CHECK_MSG(contains(r.h_ab, hab), "[%.17g, %.17g] vs %.17g", r.h_ab[0], r.h_ab[1], hab);
    CHECK_MSG(contains(r.h_ba, 0.1), "[%.17g, %.17g]", r.h_ba[0], r.h_ba[1]);
    CHECK(r.h_ab[1] - r.h_ab[0] <= 1e-9 && r.h_ba[1] - r.h_ba[0] <= 1e-9);
    CHECK_NEAR(r.where[0][0], 0, 1e-12);
    CHECK_NEAR(r.where[0][1], 0.5, 1e-4);
    fl_hausdorff_result_free(&r);
}

/* Bad input and options are rejected with the documented statuses, and no result leaks. */
static void test_bad_input_is_rejected(void)
{
    fl_mesh a = oracle_grid(1, 0, 0, 0), b = oracle_grid(1, 0, 0, 1);
    fl_hausdorff_result r;
    fl_error err;
    fl_hausdorff_options o = {0};
    o.precision = -1;
    CHECK_STATUS(fl_hausdorff_meshes(&a, &b, &o, &r, &err), FL_ERR_USAGE, &err);
    o.precision = NAN;
    CHECK_STATUS(fl_hausdorff_meshes(&a, &b, &o, &r, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_hausdorff_meshes(NULL, &b, NULL, &r, &err), FL_ERR_USAGE, &err);
    b.xyz[4] = NAN;
    CHECK_STATUS(fl_hausdorff_meshes(&a, &b, NULL, &r, &err), FL_ERR_INPUT, &err);
    b.xyz[4] = 0;
    b.tri[2] = 99;
    CHECK_STATUS(fl_hausdorff_meshes(&a, &b, NULL, &r, &err), FL_ERR_INPUT, &err);
    const double p[2] = {0, 0};
    CHECK_STATUS(fl_hausdorff_polylines(p, 1, 0, p, 1, 0, 2, NULL, &r, &err), FL_ERR_INPUT, &err);
    fl_mesh_free(&a);
    fl_mesh_free(&b);
}

/* Regression (found by the lattice budget test): a nearly collinear triangle — here the
 * bounding element of lattice points on a diagonal, collinear up to rounding — seen from a
 * query far from it relative to its width. The face solve's denominator va + vb + vc carried
 * rounding errors larger than the triangle's true |ab x ac|^2, so the degenerate case was
 * missed and the "closest point" was far off: the distance must be the nearest edge's. */
static void test_nearly_collinear_triangle_distance_is_the_edge_distance(void)
{
    const double a[3] = {0.3, 0.8, 0.1}, b[3] = {0.5, 1, 0.1}, c[3] = {0.4, 0.9, 0.1};
    const double p[3] = {0.34375, 0.859375, 0};
    double bary[3], cl[3];
    double d = sqrt(fl_sweep_triangle_closest(p, a, b, c, bary, cl));
    double o = (double)oracle_triangle(p, a, b, c);
    CHECK_NEAR(d, o, 1e-12);
    /* The same through the cursor on an 11 x 11 lattice of points: two nearby queries. */
    fl_mesh m = oracle_mesh_alloc(121, 121);
    for (uint32_t v = 0; v < 121; v++) {
        m.xyz[3 * v] = (v / 11) / 10.0, m.xyz[3 * v + 1] = (v % 11) / 10.0, m.xyz[3 * v + 2] = 0.1;
        m.tri[3 * v] = m.tri[3 * v + 1] = m.tri[3 * v + 2] = v;
    }
    fl_sweep *s;
    fl_sweep_cursor *cur;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    const double q[2][3] = {{0.34375, 0.859375, 0}, {0.3515625, 0.8515625, 0}};
    for (int i = 0; i < 2; i++) {
        fl_closest r;
        CHECK_STATUS(fl_sweep_cursor_closest(cur, q[i], 0, &r, &err), FL_OK, &err);
        CHECK_NEAR(r.distance, oracle_mesh_distance(&m, q[i]), 1e-12);
    }
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
    fl_mesh_free(&m);
}

/* A needle: two corners one ulp apart, the third 14 away, and a query on the long edges. The
 * angle at a is not small, so the per-angle degeneracy test let it through to the face solve,
 * whose barycentrics were rounding noise: distance 13.2 (the corner) instead of ~0. Found by
 * fuzz_sweep as a node's bounding triangle, where it pruned the answer (a 12-triangle mesh
 * of repeated points and one segment, replayed below). */
static void test_needle_triangle_distance_is_the_long_edge_distance(void)
{
    const double a[3] = {-8, -8, -8}, b[3] = {-8 + 0x1p-49, -8, -8 - 0x1p-49};
    const double c[3] = {3.988e-16, 3.988e-16, 5.347e-16}, p[3] = {-0.375, -0.375, -0.375};
    double bary[3], cl[3];
    double d = sqrt(fl_sweep_triangle_closest(p, a, b, c, bary, cl));
    double o = (double)oracle_triangle(p, a, b, c);
    CHECK_MSG(fabs(d - o) <= 1e-12 * 14, "needle: %.17g, oracle %.17g", d, o);
    double v[27] = {-6, 2e-300, -7.75, -7.75, -8, -8, -8, -8, -8, -8, -5.5, -8, -8, -8,
                    -8, -8, -8, -8, -8, -7.25, 2e-300, 2e-300, 2e-150, 2e-300, 2e-300, -1.25,
                    -1.625};
    uint32_t tri[36];
    for (int i = 0; i < 36; i++) tri[i] = 7;
    tri[0] = 4;
    fl_mesh m = {9, v, 12, tri};
    fl_sweep *s;
    fl_error err;
    fl_closest r;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_closest(s, p, 1, 0, &r, &err), FL_OK, &err);
    CHECK_MSG(r.distance <= 1e-12, "mesh query: %.17g (the segment passes through the query)",
              r.distance);
    fl_sweep_free(s);
}

FL_TEST_MAIN(FL_TEST_CASE(test_nearly_collinear_triangle_distance_is_the_edge_distance),
             FL_TEST_CASE(test_needle_triangle_distance_is_the_long_edge_distance),
             FL_TEST_CASE(test_parallel_squares_are_at_their_offset),
             FL_TEST_CASE(test_shifted_squares_reach_the_corner_distance),
             FL_TEST_CASE(test_mesh_against_itself_is_zero),
             FL_TEST_CASE(test_triangle_against_its_corners_is_the_circumradius),
             FL_TEST_CASE(test_sphere_against_scaled_copy),
             FL_TEST_CASE(test_cube_against_rotated_cube_matches_dense_sampling),
             FL_TEST_CASE(test_polyline_square_against_open_shifted_square),
             FL_TEST_CASE(test_bad_input_is_rejected))
