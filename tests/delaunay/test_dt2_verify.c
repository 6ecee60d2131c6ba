/* fl_dt2_verify rejects each kind of broken triangulation: a test for the checker itself, so
 * that "verify passes" in the other tests means something. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "dt2_test_util.h"
#include "fl_test.h"

static double *uniform_points(size_t n, unsigned long long seed)
{
    double *xy = malloc(2 * n * sizeof *xy);
    for (size_t i = 0; i < 2 * n; i++)
        xy[i] = fl_test_rand01(&seed);
    return xy;
}

/* Recomputes adjacency from the triangles by brute force (small inputs only). */
static void rebuild_adjacency(fl_dt2 *dt)
{
    for (size_t t = 0; t < dt->triangle_count; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = dt->tri[3 * t + (k + 1) % 3], b = dt->tri[3 * t + (k + 2) % 3];
            dt->adj[3 * t + k] = UINT32_MAX;
            for (size_t u = 0; u < dt->triangle_count; u++)
                for (int j = 0; j < 3; j++)
                    if (dt->tri[3 * u + (j + 1) % 3] == b && dt->tri[3 * u + (j + 2) % 3] == a)
                        dt->adj[3 * t + k] = (uint32_t)u;
        }
}

/* Flips the first interior edge whose quadrilateral is strictly convex; returns 0 if none. */
static int flip_some_edge(const double *xy, fl_dt2 *dt)
{
    for (size_t t = 0; t < dt->triangle_count; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t u = dt->adj[3 * t + k];
            if (u == UINT32_MAX) continue;
            uint32_t p = dt->tri[3 * t + k], q = dt->tri[3 * t + (k + 1) % 3],
                     r = dt->tri[3 * t + (k + 2) % 3], s = UINT32_MAX;
            for (int j = 0; j < 3; j++)
                if (dt->tri[3 * (size_t)u + j] != q && dt->tri[3 * (size_t)u + j] != r)
                    s = dt->tri[3 * (size_t)u + j];
            if (fl_orient2d(tu_pt(xy, p), tu_pt(xy, q), tu_pt(xy, s)) <= 0 ||
                fl_orient2d(tu_pt(xy, s), tu_pt(xy, r), tu_pt(xy, p)) <= 0)
                continue;
            uint32_t nt[3] = {p, q, s}, nu[3] = {s, r, p};
            memcpy(dt->tri + 3 * t, nt, sizeof nt);
            memcpy(dt->tri + 3 * (size_t)u, nu, sizeof nu);
            rebuild_adjacency(dt);
            return 1;
        }
    return 0;
}

static void build(const double *xy, size_t n, fl_dt2 *dt)
{
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, n, NULL, dt, &err), FL_OK, &err);
    CHECK_STATUS(fl_dt2_verify(xy, dt, &err), FL_OK, &err);
}

static void expect_violation(const double *xy, const fl_dt2 *dt, const char *words)
{
    fl_error err;
    CHECK_STATUS(fl_dt2_verify(xy, dt, &err), FL_ERR_ALGORITHM, &err);
    CHECK_MSG(strstr(err.message, words) != NULL, "message '%s' lacks '%s'", err.message, words);
}

static void test_verify_detects_a_non_delaunay_edge(void)
{
    double *xy = uniform_points(200, 41);
    fl_dt2 dt;
    build(xy, 200, &dt);
    CHECK(flip_some_edge(xy, &dt)); /* random points: the other diagonal is strictly worse */
    expect_violation(xy, &dt, "not Delaunay");
    fl_dt2_free(&dt);
    free(xy);
}

static void test_verify_detects_a_clockwise_triangle(void)
{
    double *xy = uniform_points(100, 43);
    fl_dt2 dt;
    build(xy, 100, &dt);
    uint32_t t = dt.tri[3];
    dt.tri[3] = dt.tri[4];
    dt.tri[4] = t;
    expect_violation(xy, &dt, "not counterclockwise");
    fl_dt2_free(&dt);
    free(xy);
}

static void test_verify_detects_asymmetric_adjacency(void)
{
    double *xy = uniform_points(100, 47);
    fl_dt2 dt;
    build(xy, 100, &dt);
    for (size_t i = 0; i < 3 * dt.triangle_count; i++)
        if (dt.adj[i] != UINT32_MAX) {
            dt.adj[i] = dt.adj[i] == 0 ? 1 : 0;
            break;
        }
    expect_violation(xy, &dt, "not symmetric");
    fl_dt2_free(&dt);
    free(xy);
}

static void test_verify_detects_a_wrong_hull(void)
{
    double *xy = uniform_points(100, 53);
    fl_dt2 dt;
    build(xy, 100, &dt);
    uint32_t t = dt.hull[0];
    dt.hull[0] = dt.hull[1];
    dt.hull[1] = t;
    expect_violation(xy, &dt, "hull");
    fl_dt2_free(&dt);
    free(xy);
}

/* Dropping a triangle leaves a hole: boundary edges no longer match the hull. */
static void test_verify_detects_a_missing_triangle(void)
{
    double *xy = uniform_points(100, 59);
    fl_dt2 dt;
    build(xy, 100, &dt);
    size_t last = dt.triangle_count - 1;
    for (size_t i = 0; i < 3 * last; i++)
        if (dt.adj[i] == last) dt.adj[i] = UINT32_MAX;
    dt.triangle_count = last;
    expect_violation(xy, &dt, "boundary");
    fl_dt2_free(&dt);
    free(xy);
}

/* The points changed under the triangulation: two now coincide, but only one is merged. */
static void test_verify_detects_an_unmerged_duplicate(void)
{
    double *xy = uniform_points(100, 61);
    fl_dt2 dt;
    build(xy, 100, &dt);
    xy[2 * 7] = xy[2 * 3];
    xy[2 * 7 + 1] = xy[2 * 3 + 1];
    expect_violation(xy, &dt, "duplicate_of[7]");
    fl_dt2_free(&dt);
    free(xy);
}

FL_TEST_MAIN(FL_TEST_CASE(test_verify_detects_a_non_delaunay_edge),
             FL_TEST_CASE(test_verify_detects_a_clockwise_triangle),
             FL_TEST_CASE(test_verify_detects_asymmetric_adjacency),
             FL_TEST_CASE(test_verify_detects_a_wrong_hull),
             FL_TEST_CASE(test_verify_detects_a_missing_triangle),
             FL_TEST_CASE(test_verify_detects_an_unmerged_duplicate))
