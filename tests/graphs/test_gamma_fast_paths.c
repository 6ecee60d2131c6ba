/* Every parameter regime: the default construction (Delaunay-based and output-sensitive parts)
 * against the Theorem 3.1 brute force, on random and on degenerate (lattice) sets, 2D and 3D. */
#include "gamma_oracle.h"

typedef struct regime {
    int range;
    double c[4];
} regime;

static const regime regimes[] = {
    {0, {1, 1}},
    {0, {-1, -1}},
    {0, {-1, 1}},
    {0, {1, -1}},
    {0, {0, 0}},
    {0, {0.3, 0.3}},
    {0, {-0.3, -0.3}},
    {0, {-0.15, 0.3}},
    {0, {0.25, 0.5}},
    {0, {0, -0.25}},
    {0, {0.2, -0.5}},
    {0, {-0.5, -0.9}},
    {1, {-1, 1, 0, 1}},
    {1, {-1, 1, -1, 0}},
    {1, {-0.25, 0.25, -0.25, 0}},
    {1, {-1, 1, -1, -0.9}},
    {1, {-1, 1, -0.3, 1}},
    {1, {0.2, 0.8, 0.5, 1}},
    {1, {-1, 1, 0.5, 1}},
    {1, {-1, 0, -0.6, -0.1}},
    {1, {0, 1, -1, 1}},
    {1, {-1, 1, -1, 1}},
};

static int compare_methods(const double *p, size_t n, int dim, const regime *r)
{
    fl_gamma_params gp = {r->range, {r->c[0], r->c[1], r->c[2], r->c[3]}};
    fl_graph_options fast = {FL_GAMMA_AUTO, 1, NULL, NULL},
                     slow = {FL_GAMMA_BRUTE_FORCE, 1, NULL, NULL};
    fl_graph a, b;
    fl_error err;
    CHECK_STATUS(fl_gamma_graph(p, n, dim, &gp, &fast, &a, &err), FL_OK, &err);
    CHECK_STATUS(fl_gamma_graph(p, n, dim, &gp, &slow, &b, &err), FL_OK, &err);
    int same = oracle_graph_equal(&a, &b);
    for (size_t i = 0; same && i < 2 * a.simplex_count; i++)
        same = a.params[i] == b.params[i];
    if (!same)
        fprintf(stderr, "dim %d n %zu regime %d (%g,%g,%g,%g): fast %zu vs brute %zu simplices\n",
                dim, n, r->range, r->c[0], r->c[1], r->c[2], r->c[3], a.simplex_count,
                b.simplex_count);
    fl_graph_free(&a);
    fl_graph_free(&b);
    return same;
}

static void check_all_regimes(const double *p, size_t n, int dim)
{
    for (size_t i = 0; i < sizeof regimes / sizeof regimes[0]; i++)
        CHECK(compare_methods(p, n, dim, &regimes[i]));
}

static void test_gamma_fast_equals_brute_force_random_2d(void)
{
    for (unsigned long long seed = 100; seed < 103; seed++) {
        double *p = oracle_random_points(60, 2, seed);
        check_all_regimes(p, 60, 2);
        free(p);
    }
}

static void test_gamma_fast_equals_brute_force_lattice_2d(void)
{
    for (unsigned long long seed = 200; seed < 203; seed++) {
        double *p = oracle_grid_points(30, 2, 7, seed);
        check_all_regimes(p, 30, 2);
        free(p);
    }
}

static void test_gamma_fast_equals_brute_force_random_3d(void)
{
    double *p = oracle_random_points(14, 3, 300);
    check_all_regimes(p, 14, 3);
    free(p);
}

static void test_gamma_fast_equals_brute_force_lattice_3d(void)
{
    double *p = oracle_grid_points(14, 3, 3, 400);
    check_all_regimes(p, 14, 3);
    free(p);
}

/* Clustered points (a few tight blobs) stress the sector filter: long edges between blobs. */
static void test_gamma_fast_equals_brute_force_clusters_2d(void)
{
    unsigned long long seed = 500;
    double p[2 * 80];
    for (int i = 0; i < 80; i++) {
        int blob = i % 4;
        p[2 * i] = blob * 3.0 + 0.05 * fl_test_rand01(&seed);
        p[2 * i + 1] = (blob % 2) * 2.0 + 0.05 * fl_test_rand01(&seed);
    }
    check_all_regimes(p, 80, 2);
}

FL_TEST_MAIN(FL_TEST_CASE(test_gamma_fast_equals_brute_force_random_2d),
             FL_TEST_CASE(test_gamma_fast_equals_brute_force_lattice_2d),
             FL_TEST_CASE(test_gamma_fast_equals_brute_force_random_3d),
             FL_TEST_CASE(test_gamma_fast_equals_brute_force_lattice_3d),
             FL_TEST_CASE(test_gamma_fast_equals_brute_force_clusters_2d))
