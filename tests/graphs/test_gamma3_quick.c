/* The two shortcuts of the 3D shortest-edge search (src/graphs/gamma3_edges.c, docs/gamma.md
 * "Quick drop test" and "The far part of the scan"): the quick drop test (kills only, from the 27
 * cells around the midpoint, with approximate angles) and the kd-tree walk that replaces the
 * rings beyond ring 1. Either one, if wrong, drops a pair or a third vertex the plain ring scan
 * keeps, and a triangle goes missing; so the default search must give the plain scan's
 * triangles and (c0', c1') doubles bit for bit, and the Theorem 3.1 brute force's where that
 * is affordable, on random, lattice (ties between edge lengths), thin slab, near-sphere and
 * clustered sets, and the counters must show that both shortcuts ran. */
#include "gamma_oracle.h"

#include "gamma3_test.h"

/* Default against plain (and the brute force when `brute`); returns the default's counters. */
static gamma3_stats compare(const double *p, size_t n, double kappa, int brute, const char *what)
{
    gamma3_stats fast, plain;
    fl_graph a = gamma3_test_search(p, n, kappa, GAMMA3_ALL_PAIRS, &fast);
    fl_graph b = gamma3_test_search(p, n, kappa, GAMMA3_ALL_PAIRS | GAMMA3_PLAIN_SCAN, &plain);
    CHECK_MSG(gamma3_test_same(&a, &b), "%s n %zu kappa %g: default %zu vs plain %zu triangles", what, n,
              kappa, a.simplex_count, b.simplex_count);
    CHECK(a.simplex_count > 0);
    CHECK_EQ_INT((long long)plain.quick_dropped, 0);
    CHECK_EQ_INT((long long)plain.kd_walks, 0);
    if (brute) {
        fl_graph c = gamma3_test_brute(p, n, kappa);
        CHECK_MSG(gamma3_test_same(&a, &c), "%s n %zu: default %zu vs brute force %zu triangles", what,
                  n, a.simplex_count, c.simplex_count);
        fl_graph_free(&c);
    }
    fl_graph_free(&a);
    fl_graph_free(&b);
    return fast;
}

/* gamma3_quick_angle is within G3_QUICK_ERR = 1e-5 of atan2 (its polynomial's bound is
 * 1.7e-6), densely on the circle, near the octant boundaries and at tiny/huge scales. */
static void test_gamma3_quick_angle_error_bound(void)
{
    double worst = 0;
    for (int i = 0; i < 200000; i++) {
        double t = -3.14159265358979 + 6.28318530717958 * (i + 0.5) / 200000;
        const double scale[3] = {1, 1e-200, 1e200};
        for (int k = 0; k < 3; k++) {
            double x = scale[k] * cos(t), y = scale[k] * sin(t);
            double e = fabs(remainder(gamma3_quick_angle(x, y) - atan2(y, x), 2 * 3.14159265358979));
            if (e > worst) worst = e;
        }
    }
    const double axes[8][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    for (int i = 0; i < 8; i++) {
        double e = fabs(remainder(gamma3_quick_angle(axes[i][0], axes[i][1]) -
                                      atan2(axes[i][1], axes[i][0]),
                                  2 * 3.14159265358979));
        if (e > worst) worst = e;
    }
    CHECK_MSG(worst < 1e-5, "quick angle error %g", worst);
    CHECK(worst > 0); /* it is an approximation: the bound is what the test checks */
}

/* Small random sets against the brute force, several kappas: the quick test drops pairs and the
 * kd walk runs (grids of several cells a side). */
static void test_gamma3_quick_random_equals_brute_force(void)
{
    const double kappas[2] = {0.3, 0.7};
    size_t quick = 0, walks = 0;
    for (unsigned long long seed = 950; seed < 953; seed++) {
        double *p = oracle_random_points(48, 3, seed);
        for (int k = 0; k < 2; k++) {
            gamma3_stats st = compare(p, 48, kappas[k], 1, "random");
            quick += st.quick_dropped;
            walks += st.kd_walks;
        }
        free(p);
    }
    CHECK(quick > 0);
    CHECK(walks > 0);
}

/* Larger sets, default against plain: random cube, an exact lattice (all edge lengths tie),
 * a thin slab, points near a sphere, clusters. */
static void test_gamma3_quick_structured_sets_equal_plain_scan(void)
{
    unsigned long long s = 960;
    const size_t n = 150;
    double *p = malloc(3 * n * sizeof *p);
    gamma3_stats st;
    for (size_t i = 0; i < 3 * n; i++)
        p[i] = fl_test_rand01(&s);
    st = compare(p, n, 0.5, 0, "cube");
    CHECK(st.quick_dropped > 0 && st.kd_walks > 0);
    for (size_t i = 0; i < n; i++) { /* 5 x 5 x 6 lattice */
        p[3 * i] = (double)(i % 5);
        p[3 * i + 1] = (double)(i / 5 % 5);
        p[3 * i + 2] = (double)(i / 25);
    }
    st = compare(p, n, 0.5, 0, "lattice");
    CHECK(st.quick_dropped > 0);
    for (size_t i = 0; i < n; i++) {
        p[3 * i] = fl_test_rand01(&s);
        p[3 * i + 1] = fl_test_rand01(&s);
        p[3 * i + 2] = 0.02 * fl_test_rand01(&s);
    }
    compare(p, n, 0.5, 0, "slab");
    for (size_t i = 0; i < n; i++)
        gamma3_test_sphere_point(&s, 0.05, p + 3 * i);
    compare(p, 100, 0.5, 0, "near sphere");
    const double centres[4][3] = {{0, 0, 0}, {3, 0, 0}, {0, 2, 1}, {1, 1, 4}};
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            p[3 * i + k] = centres[i % 4][k] + (0.1 + 0.2 * (double)(i % 4)) * fl_test_rand01(&s);
    compare(p, n, 0.5, 0, "clusters");
    free(p);
}

FL_TEST_MAIN(FL_TEST_CASE(test_gamma3_quick_angle_error_bound),
             FL_TEST_CASE(test_gamma3_quick_random_equals_brute_force),
             FL_TEST_CASE(test_gamma3_quick_structured_sets_equal_plain_scan))
