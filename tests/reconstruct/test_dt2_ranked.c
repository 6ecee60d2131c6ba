/* fl_dt2_build_ranked (src/delaunay, internal; 2D constriction starts from it) against the
 * public fl_dt2_build on the same points: mapped through `order`, its triangles, neighbours and
 * hull must be fl_dt2_build's, entry for entry and in the same order (constriction's results
 * are compared byte for byte with the earlier version, which built on fl_dt2_build), its
 * coordinates must be the input's, its order a bijection onto the first point of each kind, and
 * consecutive ranks must be close in the plane (the reason it exists); the spare memory it
 * lends after the triangles must not overlap them. */
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_internal.h"
#include "fl_test.h"

/* n points in the unit square, snapped to a grid of `grid` cells a side when grid > 0 (ties,
 * cocircular quadruples and duplicates). */
static double *points(size_t n, double grid, unsigned long long seed)
{
    double *xy = malloc(2 * n * sizeof *xy);
    for (size_t i = 0; i < 2 * n; i++) {
        double v = fl_test_rand01(&seed);
        xy[i] = grid > 0 ? (double)(long)(v * grid) / grid : v;
    }
    return xy;
}

static void compare(const double *xy, size_t n)
{
    fl_dt2 d;
    fl_dt2_ranked r;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, n, NULL, &d, &err), FL_OK, &err);
    CHECK_STATUS(fl_dt2_build_ranked(xy, n, NULL, &r, &err), FL_OK, &err);
    CHECK(r.point_count == d.point_count && r.unique_count == d.unique_count);
    CHECK(r.triangle_count == d.triangle_count && r.hull_count == d.hull_count);
    if (r.triangle_count != d.triangle_count || r.hull_count != d.hull_count) goto out;
    CHECK(memcmp(r.duplicate_of, d.duplicate_of, n * sizeof *r.duplicate_of) == 0);
    /* The spare memory follows the triangles, 16-byte aligned, and is free to use: filled with
     * junk here before tri and adj are compared (ASan: it lies inside tri's allocation). At
     * least 7 bytes a point (what fl_reconstruct2 puts there besides its queue) are lent. */
    const unsigned char *tri_end = (const unsigned char *)(r.tri + 3 * r.triangle_count);
    CHECK(r.spare != NULL && (const unsigned char *)r.spare >= tri_end &&
          (const unsigned char *)r.spare < tri_end + 16 && (uintptr_t)r.spare % 16 == 0);
    CHECK(r.spare_bytes >= 7 * r.unique_count);
    if (r.spare) memset(r.spare, 0xA5, r.spare_bytes);
    /* order: ranks -> distinct input points, each first of its kind exactly once */
    unsigned char *seen = calloc(n, 1);
    size_t bad = 0;
    for (size_t k = 0; k < r.unique_count; k++) {
        uint32_t i = r.order[k];
        if (i >= n || seen[i] || d.duplicate_of[i] != i) {
            bad++;
            continue;
        }
        seen[i] = 1;
        bad += r.xy[2 * k] != xy[2 * (size_t)i] || r.xy[2 * k + 1] != xy[2 * (size_t)i + 1];
    }
    free(seen);
    CHECK_EQ_INT(bad, 0);
    for (size_t j = 0; j < 3 * d.triangle_count; j++) {
        bad += r.tri[j] >= r.unique_count || r.order[r.tri[j]] != d.tri[j];
        bad += r.adj[j] != d.adj[j];
    }
    for (size_t j = 0; j < d.hull_count; j++)
        bad += r.hull[j] >= r.unique_count || r.order[r.hull[j]] != d.hull[j];
    CHECK_EQ_INT(bad, 0);
out:
    fl_dt2_ranked_free(&r);
    fl_dt2_free(&d);
}

static void test_ranked_equals_dt2_build_on_random_points(void)
{
    for (unsigned long long s = 1; s <= 4; s++) {
        double *xy = points(2000 * s, 0, s);
        compare(xy, 2000 * s);
        free(xy);
    }
}

static void test_ranked_equals_dt2_build_with_duplicates_and_ties(void)
{
    for (unsigned long long s = 1; s <= 4; s++) {
        double *xy = points(3000, s == 4 ? 8 : 30.0 * (double)s, 100 + s);
        compare(xy, 3000);
        free(xy);
    }
    double square[] = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 1}; /* cocircular, two duplicates */
    compare(square, 6);
}

/* Why the ranks are used: on 1e5 uniform points, the mean distance between the points of
 * consecutive ranks is far below that of consecutive input indices (about 0.52 for independent
 * uniform points). BRIO's rounds put a jump at each round's start, a handful in all. */
static void test_consecutive_ranks_are_close(void)
{
    size_t n = 100000;
    double *xy = points(n, 0, 7);
    fl_dt2_ranked r;
    fl_error err;
    CHECK_STATUS(fl_dt2_build_ranked(xy, n, NULL, &r, &err), FL_OK, &err);
    double sum = 0;
    for (size_t k = 1; k < r.unique_count; k++)
        sum += hypot(r.xy[2 * k] - r.xy[2 * k - 2], r.xy[2 * k + 1] - r.xy[2 * k - 1]);
    double mean = sum / (double)(r.unique_count - 1);
    CHECK_MSG(mean < 0.05, "mean distance between consecutive ranks %g", mean);
    fl_dt2_ranked_free(&r);
    free(xy);
}

static void test_ranked_rejects_bad_input_like_dt2_build(void)
{
    fl_dt2_ranked r;
    fl_error err;
    double line[] = {0, 0, 1, 1, 2, 2, 3, 3};
    double nan_pt[] = {0, 0, 1, 0, NAN, 1};
    CHECK_STATUS(fl_dt2_build_ranked(line, 4, NULL, &r, &err), FL_ERR_ALGORITHM, &err);
    CHECK(r.tri == NULL && r.order == NULL && r.xy == NULL);
    CHECK_STATUS(fl_dt2_build_ranked(nan_pt, 3, NULL, &r, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_dt2_build_ranked(line, 2, NULL, &r, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_dt2_build_ranked(NULL, 3, NULL, &r, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_dt2_build_ranked(line, 4, NULL, NULL, &err), FL_ERR_USAGE, &err);
}

FL_TEST_MAIN(FL_TEST_CASE(test_ranked_equals_dt2_build_on_random_points),
             FL_TEST_CASE(test_ranked_equals_dt2_build_with_duplicates_and_ties),
             FL_TEST_CASE(test_consecutive_ranks_are_close),
             FL_TEST_CASE(test_ranked_rejects_bad_input_like_dt2_build))
