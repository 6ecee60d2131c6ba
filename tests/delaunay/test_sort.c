/* Spatial sort (BRIO along a Hilbert curve) and exact duplicate detection. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_internal.h"
#include "fl_test.h"

static double *random_points(size_t n, int dim, unsigned long long seed)
{
    double *p = malloc(n * (size_t)dim * sizeof *p);
    for (size_t i = 0; i < n * (size_t)dim; i++)
        p[i] = fl_test_rand01(&seed);
    return p;
}

/* Every id appears exactly once in the output. */
static int is_permutation_of(const uint32_t *order, const uint32_t *ids, size_t n, size_t range)
{
    unsigned char *seen = calloc(range, 1);
    int ok = 1;
    for (size_t i = 0; i < n; i++)
        seen[ids ? ids[i] : i] = 1;
    for (size_t i = 0; i < n && ok; i++) {
        if (order[i] >= range || seen[order[i]] != 1)
            ok = 0;
        else
            seen[order[i]] = 2;
    }
    free(seen);
    return ok;
}

static double dist(const double *c, int dim, uint32_t a, uint32_t b)
{
    double s = 0;
    for (int k = 0; k < dim; k++) {
        double d = c[(size_t)a * dim + k] - c[(size_t)b * dim + k];
        s += d * d;
    }
    return sqrt(s);
}

static double mean_step(const double *c, int dim, const uint32_t *order, size_t n)
{
    double s = 0;
    for (size_t i = 1; i < n; i++)
        s += dist(c, dim, order[i - 1], order[i]);
    return s / (double)(n - 1);
}

static void test_brio_order_is_a_permutation_of_the_ids(void)
{
    for (int dim = 2; dim <= 3; dim++) {
        size_t n = 5000;
        double *p = random_points(n, dim, 11);
        uint32_t *order = malloc(n * sizeof *order);
        fl_error err;
        CHECK_STATUS(fl_dt_brio_order(p, NULL, n, dim, order, &err), FL_OK, &err);
        CHECK(is_permutation_of(order, NULL, n, n));
        /* A subset given by ids: every third point. */
        size_t m = n / 3;
        uint32_t *ids = malloc(m * sizeof *ids);
        for (size_t i = 0; i < m; i++)
            ids[i] = (uint32_t)(3 * i + 1);
        CHECK_STATUS(fl_dt_brio_order(p, ids, m, dim, order, &err), FL_OK, &err);
        CHECK(is_permutation_of(order, ids, m, n));
        free(ids);
        free(order);
        free(p);
    }
}

static void test_brio_order_is_deterministic(void)
{
    size_t n = 3000;
    double *p = random_points(n, 2, 5);
    uint32_t *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    fl_error err;
    CHECK_STATUS(fl_dt_brio_order(p, NULL, n, 2, a, &err), FL_OK, &err);
    CHECK_STATUS(fl_dt_brio_order(p, NULL, n, 2, b, &err), FL_OK, &err);
    CHECK(memcmp(a, b, n * sizeof *a) == 0);
    free(a);
    free(b);
    free(p);
}

/* Locality: consecutive points in BRIO order are far closer than in a random order (whose mean
 * step is about 0.52 in the unit square and 0.66 in the unit cube). */
static void test_brio_consecutive_points_are_close(void)
{
    for (int dim = 2; dim <= 3; dim++) {
        size_t n = 20000;
        double *p = random_points(n, dim, 99 + (unsigned)dim);
        uint32_t *order = malloc(n * sizeof *order);
        fl_error err;
        CHECK_STATUS(fl_dt_brio_order(p, NULL, n, dim, order, &err), FL_OK, &err);
        uint32_t *identity = malloc(n * sizeof *identity);
        for (size_t i = 0; i < n; i++)
            identity[i] = (uint32_t)i;
        double brio = mean_step(p, dim, order, n), random = mean_step(p, dim, identity, n);
        CHECK_MSG(brio < 0.1 * random, "dim %d: brio %g random %g", dim, brio, random);
        free(identity);
        free(order);
        free(p);
    }
}

/* On a full 2^k grid (one BRIO round) the Hilbert curve visits face-adjacent cells in turn, so
 * every step has length exactly 1 (a Morton order would jump). */
static void test_hilbert_order_on_full_grid_has_unit_steps(void)
{
    int side[2] = {16, 4};
    for (int dim = 2; dim <= 3; dim++) {
        int s = side[dim - 2];
        size_t n = dim == 2 ? (size_t)s * s : (size_t)s * s * s;
        double *p = malloc(n * (size_t)dim * sizeof *p);
        for (size_t i = 0; i < n; i++) {
            p[i * dim] = (double)(i % s);
            p[i * dim + 1] = (double)((i / s) % s);
            if (dim == 3) p[i * dim + 2] = (double)(i / ((size_t)s * s));
        }
        uint32_t *order = malloc(n * sizeof *order);
        fl_error err;
        CHECK_STATUS(fl_dt_brio_order(p, NULL, n, dim, order, &err), FL_OK, &err);
        size_t bad = 0;
        for (size_t i = 1; i < n; i++)
            bad += dist(p, dim, order[i - 1], order[i]) != 1.0;
        CHECK_EQ_INT(bad, 0);
        free(order);
        free(p);
    }
}

static void test_brio_handles_extreme_coordinate_range(void)
{
    double p[] = {-1e308, -1e308, 1e308, 1e308, 0, 0, 1e308, -1e308, -1e308, 1e308, 5e-324, 0};
    uint32_t order[6];
    fl_error err;
    CHECK_STATUS(fl_dt_brio_order(p, NULL, 6, 2, order, &err), FL_OK, &err);
    CHECK(is_permutation_of(order, NULL, 6, 6));
}

static void test_brio_and_unique_reject_non_finite_coordinates(void)
{
    double p[] = {0, 0, 1, 1, 2, NAN, 3, 3};
    double q[] = {0, 0, 0, 1, INFINITY, 1, 2, 2, 2};
    uint32_t out[4];
    size_t unique;
    fl_error err;
    CHECK_STATUS(fl_dt_brio_order(p, NULL, 4, 2, out, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "point 2") != NULL);
    CHECK_STATUS(fl_dt_unique(p, 4, 2, out, &unique, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_dt_brio_order(q, NULL, 3, 3, out, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "point 1") != NULL);
    CHECK_STATUS(fl_dt_unique(q, 3, 3, out, &unique, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_dt_brio_order(p, NULL, 4, 4, out, &err), FL_ERR_USAGE, &err);
}

/* Reference: the first j <= i whose coordinates compare equal (== treats -0.0 as +0.0). */
static size_t brute_force_reps(const double *p, size_t n, int dim, uint32_t *rep)
{
    size_t unique = 0;
    for (size_t i = 0; i < n; i++) {
        size_t j = 0;
        for (;; j++) {
            int eq = 1;
            for (int k = 0; k < dim; k++)
                eq &= p[j * dim + k] == p[i * dim + k];
            if (eq) break;
        }
        rep[i] = (uint32_t)j;
        unique += j == i;
    }
    return unique;
}

static void test_unique_finds_exactly_the_identical_points(void)
{
    for (int dim = 2; dim <= 3; dim++) {
        size_t n = 2000;
        unsigned long long seed = 7;
        double *p = malloc(n * (size_t)dim * sizeof *p);
        for (size_t i = 0; i < n; i++) {
            unsigned long long r = fl_test_rand_u64(&seed) % 4;
            for (int k = 0; k < dim; k++) {
                /* A small integer lattice (many exact repeats), -0.0 for 0, and a copy of an
                 * earlier coordinate perturbed by one ulp (must stay distinct). */
                double v = (double)(fl_test_rand_u64(&seed) % 5);
                if (r == 1 && v == 0.0) v = -0.0;
                if (r == 2 && i > 0) v = nextafter(p[(i - 1) * dim + k], 10.0);
                p[i * dim + k] = v;
            }
        }
        uint32_t *rep = malloc(n * sizeof *rep), *ref = malloc(n * sizeof *ref);
        size_t unique = 0;
        fl_error err;
        CHECK_STATUS(fl_dt_unique(p, n, dim, rep, &unique, &err), FL_OK, &err);
        size_t ref_unique = brute_force_reps(p, n, dim, ref);
        CHECK_EQ_INT(unique, ref_unique);
        CHECK(memcmp(rep, ref, n * sizeof *rep) == 0);
        CHECK_MSG(unique > 30 && unique < n / 2, "%zu unique", unique); /* both kinds present */
        free(rep);
        free(ref);
        free(p);
    }
}

static void test_unique_merges_negative_zero_with_zero(void)
{
    double p[] = {0.0, 1.0, -0.0, 1.0, 0.0, -0.0, -0.0, 0.0, 5e-324, 0.0};
    uint32_t rep[5];
    size_t unique = 0;
    fl_error err;
    CHECK_STATUS(fl_dt_unique(p, 5, 2, rep, &unique, &err), FL_OK, &err);
    CHECK_EQ_INT(unique, 3);
    CHECK_EQ_INT(rep[0], 0);
    CHECK_EQ_INT(rep[1], 0);
    CHECK_EQ_INT(rep[2], 2);
    CHECK_EQ_INT(rep[3], 2);
    CHECK_EQ_INT(rep[4], 4); /* the smallest subnormal is not zero */
}

FL_TEST_MAIN(FL_TEST_CASE(test_brio_order_is_a_permutation_of_the_ids),
             FL_TEST_CASE(test_brio_order_is_deterministic),
             FL_TEST_CASE(test_brio_consecutive_points_are_close),
             FL_TEST_CASE(test_hilbert_order_on_full_grid_has_unit_steps),
             FL_TEST_CASE(test_brio_handles_extreme_coordinate_range),
             FL_TEST_CASE(test_brio_and_unique_reject_non_finite_coordinates),
             FL_TEST_CASE(test_unique_finds_exactly_the_identical_points),
             FL_TEST_CASE(test_unique_merges_negative_zero_with_zero))
