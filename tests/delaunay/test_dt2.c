/* 2D Delaunay: every triangulation passes fl_dt2_verify, matches an independent monotone-chain
 * hull, satisfies triangles = 2n - 2 - h and (on small sets) a brute-force empty-circle check,
 * on random and highly degenerate inputs. */
#include <math.h>
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

static void test_dt2_random_uniform_points_are_delaunay(void)
{
    double *xy = uniform_points(300, 1);
    tu_check_delaunay("uniform 300", xy, 300, 1);
    free(xy);
    xy = uniform_points(20000, 2);
    tu_check_delaunay("uniform 20000", xy, 20000, 0);
    free(xy);
}

static void test_dt2_gaussian_clusters_are_delaunay(void)
{
    size_t n = 6000;
    unsigned long long seed = 3;
    double *xy = malloc(2 * n * sizeof *xy);
    for (size_t i = 0; i < n; i++) {
        /* Five clusters of very different spread (Box-Muller normals). */
        double cx = (double)(i % 5), sigma = pow(10.0, -(double)(i % 5));
        double r = sqrt(-2.0 * log(1.0 - fl_test_rand01(&seed)));
        double a = 6.283185307179586 * fl_test_rand01(&seed);
        xy[2 * i] = cx + sigma * r * cos(a);
        xy[2 * i + 1] = sigma * r * sin(a);
    }
    tu_check_delaunay("gaussian clusters", xy, n, 0);
    tu_check_delaunay("gaussian clusters (brute)", xy, 400, 1);
    free(xy);
}

/* A grid: every unit square has four cocircular corners, so almost every incircle test ties. */
static void test_dt2_empty_circle_on_integer_grid(void)
{
    int side = 30;
    size_t n = (size_t)side * side;
    double *xy = malloc(2 * n * sizeof *xy);
    for (size_t i = 0; i < n; i++) {
        xy[2 * i] = (double)(i % side);
        xy[2 * i + 1] = (double)(i / side);
    }
    tu_check_delaunay("grid 30x30", xy, n, 1);
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, n, NULL, &dt, &err), FL_OK, &err);
    CHECK_EQ_INT(dt.hull_count, 4 * (side - 1)); /* every boundary grid point is on the hull */
    CHECK_EQ_INT(dt.triangle_count, 2 * (side - 1) * (side - 1));
    fl_dt2_free(&dt);
    /* A 0.1-spaced grid: rounding makes the squares almost, but not exactly, cocircular. */
    for (size_t i = 0; i < n; i++) {
        xy[2 * i] = 0.1 * (double)(i % side);
        xy[2 * i + 1] = 0.1 * (double)(i / side);
    }
    tu_check_delaunay("grid 0.1", xy, n, 1);
    free(xy);
}

/* All lattice points on the circles x^2 + y^2 = R^2 for R = 5525 (180 points) and R = 325
 * (60 points), scaled by 2^-10 (exact), plus the common center. */
static size_t circle_points(double *xy, long r)
{
    size_t m = 0;
    for (long x = -r; x <= r; x++) {
        long y2 = r * r - x * x, y = (long)llround(sqrt((double)y2));
        if (y * y != y2) continue;
        xy[2 * m] = ldexp((double)x, -10);
        xy[2 * m + 1] = ldexp((double)y, -10);
        m++;
        if (y != 0) {
            xy[2 * m] = ldexp((double)x, -10);
            xy[2 * m + 1] = ldexp((double)-y, -10);
            m++;
        }
    }
    return m;
}

static void test_dt2_empty_circle_on_cocircular_points(void)
{
    double *xy = malloc(2 * 400 * sizeof *xy);
    size_t outer = circle_points(xy, 5525);
    CHECK_EQ_INT(outer, 180);
    tu_check_delaunay("one circle", xy, outer, 1);
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, outer, NULL, &dt, &err), FL_OK, &err);
    CHECK_EQ_INT(dt.hull_count, outer);
    CHECK_EQ_INT(dt.triangle_count, outer - 2);
    fl_dt2_free(&dt);
    size_t inner = circle_points(xy + 2 * outer, 325);
    CHECK_EQ_INT(inner, 60);
    size_t n = outer + inner;
    xy[2 * n] = xy[2 * n + 1] = 0.0;
    tu_check_delaunay("two circles and center", xy, n + 1, 1);
    free(xy);
}

/* 2048 lattice points on one circle, x^2 + y^2 = N with N = 5*13*17*29*37*41*53*61*73 (a product
 * of nine primes = 1 mod 4 has 4 * 2^9 representations; N < 2^53, so all is exact). Every
 * in-circle test among them ties: the perturbation alone shapes the triangulation. */
static void test_dt2_thousands_of_exactly_cocircular_points(void)
{
    long long n2 = 5LL * 13 * 17 * 29 * 37 * 41 * 53 * 61 * 73, r = (long long)sqrt((double)n2);
    double *xy = malloc(2 * 2048 * sizeof *xy);
    size_t m = 0;
    for (long long x = -r; x <= r && m + 2 <= 2048; x++) {
        long long y2 = n2 - x * x, y = (long long)llround(sqrt((double)y2));
        while (y * y > y2)
            y--;
        while ((y + 1) * (y + 1) <= y2)
            y++;
        if (y * y != y2) continue;
        xy[2 * m] = (double)x;
        xy[2 * m + 1] = (double)y;
        m++;
        if (y != 0) {
            xy[2 * m] = (double)x;
            xy[2 * m + 1] = (double)-y;
            m++;
        }
    }
    CHECK_EQ_INT(m, 2048);
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, m, NULL, &dt, &err), FL_OK, &err);
    CHECK_STATUS(fl_dt2_verify(xy, &dt, &err), FL_OK, &err);
    CHECK_EQ_INT(dt.hull_count, m);
    CHECK_EQ_INT(dt.triangle_count, m - 2);
    fl_dt2_free(&dt);
    free(xy);
}

static void test_dt2_three_four_and_five_points(void)
{
    double cw[] = {0, 0, 0, 1, 1, 0};
    tu_check_delaunay("3 points clockwise", cw, 3, 1);
    double square[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    tu_check_delaunay("square", square, 4, 1);
    tu_check_delaunay("square and center", square, 5, 1);
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(square, 4, NULL, &dt, &err), FL_OK, &err);
    CHECK_EQ_INT(dt.triangle_count, 2);
    CHECK_EQ_INT(dt.hull_count, 4);
    fl_dt2_free(&dt);
    CHECK_STATUS(fl_dt2_build(square, 5, NULL, &dt, &err), FL_OK, &err);
    CHECK_EQ_INT(dt.triangle_count, 4);
    fl_dt2_free(&dt);
}

/* Points drawn from a 20 x 20 lattice with repeats (some with -0.0): the representatives are
 * exactly the distinct lattice points hit, each duplicate points to the first copy. */
static void test_dt2_duplicates_are_merged_and_reported(void)
{
    size_t n = 3000;
    unsigned long long seed = 17;
    double *xy = malloc(2 * n * sizeof *xy);
    int first[400];
    size_t distinct = 0;
    for (int c = 0; c < 400; c++)
        first[c] = -1;
    for (size_t i = 0; i < n; i++) {
        int cx = (int)(fl_test_rand_u64(&seed) % 20), cy = (int)(fl_test_rand_u64(&seed) % 20);
        xy[2 * i] = cx == 0 && (i & 1) ? -0.0 : (double)cx;
        xy[2 * i + 1] = (double)cy;
        if (first[cy * 20 + cx] < 0) {
            first[cy * 20 + cx] = (int)i;
            distinct++;
        }
    }
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, n, NULL, &dt, &err), FL_OK, &err);
    CHECK_EQ_INT(dt.unique_count, distinct);
    size_t wrong = 0;
    for (size_t i = 0; i < n; i++) {
        int cx = (int)xy[2 * i], cy = (int)xy[2 * i + 1];
        wrong += dt.duplicate_of[i] != (uint32_t)first[cy * 20 + cx];
    }
    CHECK_EQ_INT(wrong, 0);
    CHECK_STATUS(fl_dt2_verify(xy, &dt, &err), FL_OK, &err);
    fl_dt2_free(&dt);
    tu_check_delaunay("lattice with duplicates", xy, n, 1);
    free(xy);
}

static void test_dt2_collinear_points_are_a_clear_error(void)
{
    double xy[2 * 12];
    for (int i = 0; i < 12; i++) {
        xy[2 * i] = (double)(i % 9);
        xy[2 * i + 1] = 2.0 * (double)(i % 9) + 1.0; /* three duplicates, too */
    }
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, 12, NULL, &dt, &err), FL_ERR_ALGORITHM, &err);
    CHECK(strstr(err.message, "all 9 distinct points are collinear") != NULL);
    CHECK(strstr(err.message, "1-dimensional") != NULL);
    CHECK(dt.tri == NULL && dt.duplicate_of == NULL && dt.triangle_count == 0);
    fl_dt2_free(&dt);
}

/* n collinear points and one off the line: all n + 1 are hull vertices, n - 1 triangles. */
static void test_dt2_collinear_points_plus_one(void)
{
    double xy[2 * 11];
    for (int i = 0; i < 10; i++) {
        xy[2 * i] = (double)((i * 7) % 10); /* shuffled along the line */
        xy[2 * i + 1] = 0.0;
    }
    xy[20] = 3.0;
    xy[21] = 5.0;
    tu_check_delaunay("collinear plus one", xy, 11, 1);
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, 11, NULL, &dt, &err), FL_OK, &err);
    CHECK_EQ_INT(dt.triangle_count, 9);
    CHECK_EQ_INT(dt.hull_count, 11);
    fl_dt2_free(&dt);
}

static void test_dt2_rejects_bad_input(void)
{
    fl_dt2 dt;
    fl_error err;
    double two[] = {0, 0, 1, 1, 0, 0, 1, 1};
    CHECK_STATUS(fl_dt2_build(two, 4, NULL, &dt, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "at least 3 distinct points, got 2") != NULL);
    CHECK_STATUS(fl_dt2_build(NULL, 0, NULL, &dt, &err), FL_ERR_INPUT, &err);
    double nan_pt[] = {0, 0, 1, 0, 0, NAN};
    CHECK_STATUS(fl_dt2_build(nan_pt, 3, NULL, &dt, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_dt2_build(NULL, 3, NULL, &dt, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_dt2_build(two, 3, NULL, NULL, &err), FL_ERR_USAGE, &err);
}

static void test_dt2_circumcenters_are_equidistant_from_corners(void)
{
    size_t n = 2000;
    double *xy = uniform_points(n, 23);
    fl_dt2_options opt = {0};
    opt.want_circumcenters = 1;
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, n, &opt, &dt, &err), FL_OK, &err);
    size_t bad = 0;
    for (size_t t = 0; t < dt.triangle_count; t++) {
        const double *c = dt.circumcenters + 2 * t;
        double r[3];
        for (int k = 0; k < 3; k++)
            r[k] = hypot(c[0] - xy[2 * dt.tri[3 * t + k]], c[1] - xy[2 * dt.tri[3 * t + k] + 1]);
        bad += fabs(r[1] - r[0]) > 1e-9 * r[0] || fabs(r[2] - r[0]) > 1e-9 * r[0];
    }
    CHECK_EQ_INT(bad, 0);
    fl_dt2_free(&dt);
    CHECK_STATUS(fl_dt2_build(xy, n, NULL, &dt, &err), FL_OK, &err);
    CHECK(dt.circumcenters == NULL);
    fl_dt2_free(&dt);
    free(xy);
}

typedef struct progress_log {
    int calls, cancel_at;
    double last;
    int monotone;
} progress_log;

static int record_progress(void *user, const char *stage, double fraction)
{
    progress_log *log = user;
    log->monotone &= fraction >= log->last && fraction <= 1.0 && stage != NULL;
    log->last = fraction;
    return ++log->calls == log->cancel_at;
}

static void test_dt2_reports_progress_and_can_be_cancelled(void)
{
    size_t n = 140000;
    double *xy = uniform_points(n, 29);
    progress_log log = {0, 0, 0.0, 1};
    fl_dt2_options opt = {record_progress, &log, 0};
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, n, &opt, &dt, &err), FL_OK, &err);
    CHECK(log.calls >= 3 && log.monotone && log.last == 1.0);
    fl_dt2_free(&dt);
    progress_log stop = {0, 1, 0.0, 1};
    opt.progress_user = &stop;
    CHECK_STATUS(fl_dt2_build(xy, n, &opt, &dt, &err), FL_ERR_ALGORITHM, &err);
    CHECK(strstr(err.message, "cancelled") != NULL && dt.tri == NULL);
    free(xy);
}

/* In general position the Delaunay triangulation is unique: a permuted input must give the same
 * triangles (as sets of points), although the order of insertion and the indices differ. */
static int cmp_triple(const void *a, const void *b)
{
    return memcmp(a, b, 3 * sizeof(uint32_t));
}

static uint32_t *canonical_triangles(const fl_dt2 *dt, const uint32_t *rename)
{
    uint32_t *t = malloc(3 * dt->triangle_count * sizeof *t);
    for (size_t i = 0; i < dt->triangle_count; i++) {
        uint32_t v[3];
        for (int k = 0; k < 3; k++)
            v[k] = rename[dt->tri[3 * i + k]];
        int m = v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
        for (int k = 0; k < 3; k++)
            t[3 * i + k] = v[(m + k) % 3]; /* rotate smallest first */
    }
    qsort(t, dt->triangle_count, 3 * sizeof *t, cmp_triple);
    return t;
}

static void test_dt2_is_unique_for_points_in_general_position(void)
{
    size_t n = 5000;
    double *xy = uniform_points(n, 31), *perm_xy = malloc(2 * n * sizeof *perm_xy);
    uint32_t *perm = malloc(n * sizeof *perm), *identity = malloc(n * sizeof *identity);
    unsigned long long seed = 37;
    for (size_t i = 0; i < n; i++)
        perm[i] = identity[i] = (uint32_t)i;
    for (size_t i = n; i > 1; i--) {
        size_t j = fl_test_rand_u64(&seed) % i;
        uint32_t t = perm[i - 1];
        perm[i - 1] = perm[j];
        perm[j] = t;
    }
    for (size_t i = 0; i < n; i++) { /* perm_xy[i] = xy[perm[i]] */
        perm_xy[2 * i] = xy[2 * (size_t)perm[i]];
        perm_xy[2 * i + 1] = xy[2 * (size_t)perm[i] + 1];
    }
    fl_dt2 a, b;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, n, NULL, &a, &err), FL_OK, &err);
    CHECK_STATUS(fl_dt2_build(perm_xy, n, NULL, &b, &err), FL_OK, &err);
    CHECK_EQ_INT(a.triangle_count, b.triangle_count);
    if (a.triangle_count == b.triangle_count) {
        uint32_t *ta = canonical_triangles(&a, identity), *tb = canonical_triangles(&b, perm);
        CHECK(memcmp(ta, tb, 3 * a.triangle_count * sizeof *ta) == 0);
        free(ta);
        free(tb);
    }
    fl_dt2_free(&a);
    fl_dt2_free(&b);
    free(perm);
    free(identity);
    free(perm_xy);
    free(xy);
}

/* A grid scaled by 2^-1060 (subnormal spacing) and by 2^1000: exact predicates do not care. */
static void test_dt2_grid_at_extreme_scales(void)
{
    int side = 12;
    size_t n = (size_t)side * side;
    double *xy = malloc(2 * n * sizeof *xy);
    int scales[2] = {-1060, 1000};
    for (int s = 0; s < 2; s++) {
        for (size_t i = 0; i < n; i++) {
            xy[2 * i] = ldexp((double)(i % side), scales[s]);
            xy[2 * i + 1] = ldexp((double)(i / side), scales[s]);
        }
        tu_check_delaunay(s == 0 ? "subnormal grid" : "huge grid", xy, n, 1);
    }
    free(xy);
}

/* Many points on one line, a few off it: long chains of collinear hull and interior edges. */
static void test_dt2_many_collinear_points_and_a_few_others(void)
{
    size_t n = 1003;
    double *xy = malloc(2 * n * sizeof *xy);
    for (size_t i = 0; i < 1000; i++) {
        xy[2 * i] = (double)((i * 389) % 1000); /* a permutation of 0..999 */
        xy[2 * i + 1] = 0.5 * xy[2 * i];
    }
    double extra[6] = {500, 400, 100, -300, 900, 10};
    memcpy(xy + 2000, extra, sizeof extra);
    tu_check_delaunay("line plus three", xy, n, 1);
    free(xy);
}

/* Points on a circle computed with cos/sin: nearly, not exactly, cocircular, the classic way to
 * break inexact incircle tests. */
static void test_dt2_nearly_cocircular_points(void)
{
    size_t n = 2001;
    double *xy = malloc(2 * n * sizeof *xy);
    for (size_t i = 0; i + 1 < n; i++) {
        double a = 6.283185307179586 * (double)((i * 7919) % 2000) / 2000.0;
        xy[2 * i] = cos(a);
        xy[2 * i + 1] = sin(a);
    }
    xy[2 * n - 2] = xy[2 * n - 1] = 0.0;
    tu_check_delaunay("nearly cocircular", xy, n, 0);
    tu_check_delaunay("nearly cocircular (brute)", xy + 2 * 1700, 301, 1);
    free(xy);
}

/* Many small sets on a 5 x 5 lattice: duplicates, collinear runs and cocircular quadruples
 * everywhere. Each set either triangulates correctly or is all collinear, and the collinear
 * verdict agrees with a direct check of every triple. */
static int all_collinear(const double *xy, size_t n)
{
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            for (size_t k = 0; k < n; k++)
                if (fl_orient2d(xy + 2 * i, xy + 2 * j, xy + 2 * k) != 0) return 0;
    return 1;
}

static void test_dt2_small_degenerate_lattice_sets(void)
{
    unsigned long long seed = 71;
    double xy[2 * 40];
    int built = 0;
    for (int trial = 0; trial < 300; trial++) {
        size_t n = 3 + (size_t)(fl_test_rand_u64(&seed) % 38);
        int span = trial % 3 == 0 ? 2 : 5;
        for (size_t i = 0; i < 2 * n; i++)
            xy[i] = (double)(fl_test_rand_u64(&seed) % span);
        fl_dt2 dt;
        fl_error err;
        fl_status st = fl_dt2_build(xy, n, NULL, &dt, &err);
        if (st == FL_OK) {
            built++;
            CHECK_STATUS(fl_dt2_verify(xy, &dt, &err), FL_OK, &err);
            CHECK(tu_hull_matches(xy, &dt));
            CHECK_EQ_INT(tu_empty_circle_violations(xy, &dt), 0);
            CHECK(!all_collinear(xy, n));
            fl_dt2_free(&dt);
        } else {
            CHECK_MSG(st == FL_ERR_INPUT || (st == FL_ERR_ALGORITHM && all_collinear(xy, n)),
                      "trial %d: %s", trial, err.message);
        }
    }
    CHECK(built > 200);
}

FL_TEST_MAIN(FL_TEST_CASE(test_dt2_random_uniform_points_are_delaunay),
             FL_TEST_CASE(test_dt2_gaussian_clusters_are_delaunay),
             FL_TEST_CASE(test_dt2_empty_circle_on_integer_grid),
             FL_TEST_CASE(test_dt2_empty_circle_on_cocircular_points),
             FL_TEST_CASE(test_dt2_three_four_and_five_points),
             FL_TEST_CASE(test_dt2_duplicates_are_merged_and_reported),
             FL_TEST_CASE(test_dt2_collinear_points_are_a_clear_error),
             FL_TEST_CASE(test_dt2_collinear_points_plus_one),
             FL_TEST_CASE(test_dt2_rejects_bad_input),
             FL_TEST_CASE(test_dt2_circumcenters_are_equidistant_from_corners),
             FL_TEST_CASE(test_dt2_reports_progress_and_can_be_cancelled),
             FL_TEST_CASE(test_dt2_is_unique_for_points_in_general_position),
             FL_TEST_CASE(test_dt2_grid_at_extreme_scales),
             FL_TEST_CASE(test_dt2_many_collinear_points_and_a_few_others),
             FL_TEST_CASE(test_dt2_nearly_cocircular_points),
             FL_TEST_CASE(test_dt2_small_degenerate_lattice_sets),
             FL_TEST_CASE(test_dt2_thousands_of_exactly_cocircular_points))
