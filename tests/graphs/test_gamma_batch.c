/* fl_gamma_simplices_params (the ring scan of gamma_batch.c) against the brute force of
 * Theorem 3.1 for one simplex (fl_gamma_simplex_params, every point tested): the same found
 * flag and the same (c0', c1') bit for bit, on random, degenerate (lattice, cospherical,
 * collinear runs) and clustered sets in 2D and 3D, for simplices between near neighbours (the
 * case the grid prunes) and random ones (long, often on the hull: the scan must not stop early). */
#include <math.h>
#include <string.h>

#include "fl_test.h"
#include "flintstone.h"

enum { MAXN = 400 };

static int same_double(double a, double b)
{
    return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}

/* The index of the point nearest to p[i] among the first n, other than i and `skip`. */
static uint32_t nearest(const double *p, size_t n, int dim, size_t i, uint32_t skip)
{
    double best = INFINITY;
    uint32_t b = 0;
    for (size_t j = 0; j < n; j++) {
        if (j == i || j == skip) continue;
        double d = 0;
        for (int k = 0; k < dim; k++)
            d += (p[dim * j + k] - p[dim * i + k]) * (p[dim * j + k] - p[dim * i + k]);
        if (d < best) best = d, b = (uint32_t)j;
    }
    return b;
}

static void compare_on(const double *p, size_t n, int dim, unsigned long long seed)
{
    enum { M = 600 };
    static uint32_t s[3 * M];
    static double c0[M], c1[M];
    static int found[M];
    size_t m = 0;
    for (size_t i = 0; i < n && m < M / 2; i++) { /* near-neighbour simplices */
        uint32_t a = nearest(p, n, dim, i, (uint32_t)i), b = nearest(p, n, dim, i, a);
        s[dim * m] = (uint32_t)i, s[dim * m + 1] = a;
        if (dim == 3) s[dim * m + 2] = b;
        m++;
    }
    while (m < M) { /* random simplices, distinct vertices */
        uint32_t v[3];
        for (int k = 0; k < dim; k++) {
            int again;
            do {
                v[k] = (uint32_t)(fl_test_rand_u64(&seed) % n);
                again = 0;
                for (int j = 0; j < k; j++) again |= v[j] == v[k];
            } while (again);
            s[dim * m + k] = v[k];
        }
        m++;
    }
    fl_error err;
    CHECK_STATUS(fl_gamma_simplices_params(p, n, dim, s, m, c0, c1, found, &err), FL_OK, &err);
    size_t mismatches = 0, with_params = 0;
    for (size_t i = 0; i < m; i++) {
        double b0 = NAN, b1 = NAN;
        int r = fl_gamma_simplex_params(p, n, dim, s + dim * i, &b0, &b1);
        CHECK(r == 0 || r == 1);
        if (r == 0) b0 = b1 = NAN;
        with_params += r == 1;
        if (r != found[i] || !same_double(b0, c0[i]) || !same_double(b1, c1[i])) {
            if (mismatches++ < 3)
                CHECK_MSG(0, "dim %d simplex %zu: brute force %d (%.17g, %.17g), batch %d (%.17g, %.17g)",
                          dim, i, r, b0, b1, found[i], c0[i], c1[i]);
        }
    }
    CHECK_EQ_INT(mismatches, 0);
    CHECK(with_params > m / 4); /* the sets are not all blocked: the comparison has content */
    /* the minimum over the Delaunay ones (c1' >= 0: the ball pruning of min_c1), over the
     * non-Delaunay ones (the lens pruning), and over all (blocked ones count as -1) */
    {
        size_t k = 0;
        double want = NAN;
        static uint32_t sd[3 * M];
        for (size_t i = 0; i < m; i++) {
            if (!(found[i] && c1[i] >= 0)) continue;
            memcpy(sd + dim * k, s + dim * i, dim * sizeof *s);
            k++;
            if (isnan(want) || c1[i] < want) want = c1[i];
        }
        double got;
        size_t at;
        CHECK_STATUS(fl_gamma_simplices_min_c1(p, n, dim, sd, k, &got, &at, &err), FL_OK, &err);
        CHECK_MSG(same_double(got, want), "dim %d Delaunay: min c1' %.17g, brute force %.17g",
                  dim, got, want);
        CHECK(k > 10); /* enough Delaunay simplices for the pruning to act */
        if (k) {
            double b0, b1;
            CHECK(at < k && fl_gamma_simplex_params(p, n, dim, sd + dim * at, &b0, &b1) == 1 &&
                  same_double(b1, want));
        }
    }
    for (int pass = 0; pass < 2; pass++) {
        size_t k = 0;
        double want = NAN;
        for (size_t i = 0; i < m; i++) {
            double v = found[i] ? c1[i] : -1;
            if (pass == 0 && !(found[i] && c1[i] < 0)) continue;
            memmove(s + dim * k, s + dim * i, dim * sizeof *s);
            k++;
            if (isnan(want) || v < want) want = v;
        }
        double got;
        size_t at;
        CHECK_STATUS(fl_gamma_simplices_min_c1(p, n, dim, s, k, &got, &at, &err), FL_OK, &err);
        CHECK_MSG(same_double(got, want), "dim %d pass %d: min c1' %.17g, brute force %.17g", dim,
                  pass, got, want);
        if (k) {
            CHECK(at < k);
            double b0, b1;
            int r = fl_gamma_simplex_params(p, n, dim, s + dim * at, &b0, &b1);
            CHECK(same_double(r == 1 ? b1 : -1, want));
        }
        /* recompute params for the next pass: s was compacted */
        if (pass == 0) {
            CHECK_STATUS(fl_gamma_simplices_params(p, n, dim, s, k, c0, c1, found, &err), FL_OK,
                         &err);
            m = k;
        }
    }
}

static void test_batch_equals_brute_force_random(void)
{
    static double p[3 * MAXN];
    unsigned long long seed = 11;
    for (int dim = 2; dim <= 3; dim++) {
        for (size_t i = 0; i < (size_t)dim * MAXN; i++) p[i] = fl_test_rand01(&seed);
        compare_on(p, MAXN, dim, 100 + (unsigned long long)dim);
    }
}

/* Integer lattices: many points exactly on H, on circles and spheres through the vertices. */
static void test_batch_equals_brute_force_lattice(void)
{
    static double p[3 * MAXN];
    size_t n = 0;
    for (int x = 0; x < 7; x++)
        for (int y = 0; y < 7; y++)
            for (int z = 0; z < 7 && n < 300; z++, n++)
                p[3 * n] = x, p[3 * n + 1] = y, p[3 * n + 2] = z;
    compare_on(p, n, 3, 7);
    n = 0;
    for (int x = 0; x < 15; x++)
        for (int y = 0; y < 15; y++, n++) p[2 * n] = x, p[2 * n + 1] = y;
    compare_on(p, n, 2, 8);
}

/* Points on a circle / sphere (cocircular, cospherical ties) and two far clusters (witnesses far
 * from the centre of a long simplex). */
static void test_batch_equals_brute_force_sphere_and_clusters(void)
{
    static double p[3 * MAXN];
    unsigned long long seed = 21;
    size_t n = 200;
    for (size_t i = 0; i < n; i++) {
        double t = 6.283185307179586 * (double)i / (double)n;
        p[2 * i] = cos(t), p[2 * i + 1] = sin(t);
    }
    compare_on(p, n, 2, 9);
    for (size_t i = 0; i < n; i++) {
        double z = 2 * fl_test_rand01(&seed) - 1, t = 6.283185307179586 * fl_test_rand01(&seed);
        double r = sqrt(1 - z * z);
        p[3 * i] = r * cos(t), p[3 * i + 1] = r * sin(t), p[3 * i + 2] = z;
    }
    compare_on(p, n, 3, 10);
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            p[3 * i + k] = (i % 2) * (k == 0 ? 50.0 : 0.0) + 0.1 * fl_test_rand01(&seed);
    compare_on(p, n, 3, 12);
}

static void test_batch_rejects_bad_input_and_writes_nothing(void)
{
    double p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0}, c0 = 7, c1 = 7;
    uint32_t bad[3] = {0, 1, 3}, rep[3] = {0, 1, 1};
    fl_error err;
    CHECK_STATUS(fl_gamma_simplices_params(p, 3, 3, bad, 1, &c0, &c1, NULL, &err), FL_ERR_INPUT,
                 &err);
    CHECK_STATUS(fl_gamma_simplices_params(p, 3, 3, rep, 1, &c0, &c1, NULL, &err), FL_ERR_INPUT,
                 &err);
    CHECK(c0 == 7 && c1 == 7);
    double dup[9] = {0, 0, 0, 1, 0, 0, 0, 0, 0};
    uint32_t ok[3] = {0, 1, 2};
    CHECK_STATUS(fl_gamma_simplices_params(dup, 3, 3, ok, 1, &c0, &c1, NULL, &err), FL_ERR_INPUT,
                 &err);
    double nan_pt[9] = {0, 0, 0, 1, NAN, 0, 0, 1, 0};
    CHECK_STATUS(fl_gamma_simplices_params(nan_pt, 3, 3, ok, 1, &c0, &c1, NULL, &err),
                 FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_gamma_simplices_params(p, 3, 4, ok, 1, &c0, &c1, NULL, &err), FL_ERR_USAGE,
                 &err);
    CHECK_STATUS(fl_gamma_simplices_params(p, 3, 3, NULL, 1, &c0, &c1, NULL, &err), FL_ERR_USAGE,
                 &err);
    CHECK_STATUS(fl_gamma_simplices_params(p, 3, 3, NULL, 0, NULL, NULL, NULL, &err), FL_OK, &err);
    double mn = 0;
    size_t at = 5;
    CHECK_STATUS(fl_gamma_simplices_min_c1(p, 3, 3, NULL, 0, &mn, &at, &err), FL_OK, &err);
    CHECK(isnan(mn) && at == 0);
    CHECK_STATUS(fl_gamma_simplices_min_c1(p, 3, 3, bad, 1, &mn, NULL, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_gamma_simplices_min_c1(dup, 3, 3, ok, 1, &mn, NULL, &err), FL_ERR_INPUT,
                 &err);
}

FL_TEST_MAIN(FL_TEST_CASE(test_batch_equals_brute_force_random),
             FL_TEST_CASE(test_batch_equals_brute_force_lattice),
             FL_TEST_CASE(test_batch_equals_brute_force_sphere_and_clusters),
             FL_TEST_CASE(test_batch_rejects_bad_input_and_writes_nothing))
