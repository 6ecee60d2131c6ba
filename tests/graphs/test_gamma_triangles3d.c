/* The 3D non-Delaunay triangle search (src/graphs/gamma_triangles.c) against the Theorem 3.1
 * brute force: same triangles and the same (c0', c1') doubles, for every regime with c2 < 0
 * (c1 < 0 for γ(c0,c1)), on random, lattice, cospherical, clustered and sphere-surface sets. */
#include "gamma_oracle.h"

typedef struct regime {
    int range;
    double c[4];
} regime;

/* Every regime that reaches below c1' = 0 with c1' >= -kappa, kappa < 1 (the search's domain),
 * plus kappa = 1 (brute force) as a control. */
static const regime regimes[] = {
    {1, {-1, 1, -0.5, -1e-300}}, /* the non-Delaunay part alone */
    {1, {-1, 1, -0.1, -1e-300}},
    {1, {-1, 1, -0.9, -1e-300}},
    {1, {-1, 1, -0.3, 1}},    /* Delaunay part and non-Delaunay part together */
    {1, {-1, 0, -0.6, -0.1}}, /* c0' <= 0: centres on opposite sides of the plane */
    {1, {0, 1, -0.7, -0.05}}, /* c0' >= 0: both centres on one side */
    {1, {-0.25, 0.25, -0.25, 0}},
    {1, {-1, 1, -0.99, -0.9}}, /* only deep lenses */
    {0, {-0.3, -0.3}},         /* lens of two equal balls (Lemma 3.2) */
    {0, {0, -0.25}},
    {0, {0.2, -0.5}},
    {0, {-0.5, -0.9}},
    {1, {-1, 1, -1, 0}}, /* kappa = 1: brute force on both sides */
};

static int compare_methods(const double *p, size_t n, const regime *r)
{
    fl_gamma_params gp = {r->range, {r->c[0], r->c[1], r->c[2], r->c[3]}};
    fl_graph_options fast = {FL_GAMMA_AUTO, 1, NULL, NULL},
                     slow = {FL_GAMMA_BRUTE_FORCE, 1, NULL, NULL};
    fl_graph a, b;
    fl_error err;
    CHECK_STATUS(fl_gamma_graph(p, n, 3, &gp, &fast, &a, &err), FL_OK, &err);
    CHECK_STATUS(fl_gamma_graph(p, n, 3, &gp, &slow, &b, &err), FL_OK, &err);
    int same = oracle_graph_equal(&a, &b);
    for (size_t i = 0; same && i < 2 * a.simplex_count; i++)
        same = a.params[i] == b.params[i];
    if (!same)
        fprintf(stderr, "n %zu regime %d (%g,%g,%g,%g): fast %zu vs brute %zu triangles\n", n,
                r->range, r->c[0], r->c[1], r->c[2], r->c[3], a.simplex_count, b.simplex_count);
    fl_graph_free(&a);
    fl_graph_free(&b);
    return same;
}

/* The set must produce non-Delaunay triangles for the comparison to test the search. */
static size_t non_delaunay_count(const double *p, size_t n)
{
    fl_gamma_params gp = {1, {-1, 1, -0.5, -1e-300}};
    fl_graph g;
    fl_error err;
    CHECK_STATUS(fl_gamma_graph(p, n, 3, &gp, NULL, &g, &err), FL_OK, &err);
    size_t count = g.simplex_count;
    fl_graph_free(&g);
    return count;
}

static void check_all_regimes(const double *p, size_t n)
{
    CHECK(non_delaunay_count(p, n) > 0);
    for (size_t i = 0; i < sizeof regimes / sizeof regimes[0]; i++)
        CHECK(compare_methods(p, n, &regimes[i]));
}

static void test_triangles3d_equal_brute_force_random_cube(void)
{
    for (unsigned long long seed = 700; seed < 703; seed++) {
        double *p = oracle_random_points(26, 3, seed);
        check_all_regimes(p, 26);
        free(p);
    }
}

/* Lattice points: coplanar, cocircular and cospherical subsets, points on triangles' planes. */
static void test_triangles3d_equal_brute_force_lattice(void)
{
    for (unsigned long long seed = 710; seed < 712; seed++) {
        double *p = oracle_grid_points(24, 3, 3, seed);
        check_all_regimes(p, 24);
        free(p);
    }
}

/* Integer points on the sphere of radius 5 (all cospherical: every triangle has an empty ball
 * only through the whole sphere) plus a few inside and outside. */
static void test_triangles3d_equal_brute_force_cospherical(void)
{
    double p[3 * 40];
    size_t n = 0;
    const int base[][3] = {{5, 0, 0}, {3, 4, 0}, {4, 3, 0}, {0, 3, 4}, {4, 0, 3}};
    for (size_t b = 0; b < sizeof base / sizeof base[0] && n < 30; b++)
        for (int sx = -1; sx <= 1; sx += 2)
            for (int sy = -1; sy <= 1; sy += 2) {
                double q[3] = {sx * base[b][0], sy * base[b][1], base[b][2]};
                int dup = 0;
                for (size_t i = 0; i < n; i++)
                    dup |= p[3 * i] == q[0] && p[3 * i + 1] == q[1] && p[3 * i + 2] == q[2];
                if (!dup) {
                    memcpy(p + 3 * n, q, sizeof q);
                    n++;
                }
            }
    const double extra[][3] = {{0, 0, 0}, {1, 1, 1}, {0, 0, 7}, {-2, 1, -1}};
    for (size_t i = 0; i < 4; i++, n++)
        memcpy(p + 3 * n, extra[i], sizeof extra[i]);
    check_all_regimes(p, n);
}

/* Points on the unit sphere (the dense case: nearly every triangle has a shallow lens). */
static void test_triangles3d_equal_brute_force_sphere_surface(void)
{
    unsigned long long seed = 720;
    double p[3 * 22];
    for (int i = 0; i < 22; i++) {
        double q[3], s;
        do {
            s = 0;
            for (int k = 0; k < 3; k++) {
                q[k] = 2 * fl_test_rand01(&seed) - 1;
                s += q[k] * q[k];
            }
        } while (s > 1 || s < 0.01);
        for (int k = 0; k < 3; k++)
            p[3 * i + k] = q[k] / sqrt(s);
    }
    check_all_regimes(p, 22);
}

/* Two tight blobs far apart: long triangles between blobs, witnesses far from the centre. */
static void test_triangles3d_equal_brute_force_clusters(void)
{
    unsigned long long seed = 730;
    double p[3 * 24];
    for (int i = 0; i < 24; i++)
        for (int k = 0; k < 3; k++)
            p[3 * i + k] = (i % 2) * (k == 0 ? 5.0 : 0.0) + 0.1 * fl_test_rand01(&seed);
    check_all_regimes(p, 24);
}

FL_TEST_MAIN(FL_TEST_CASE(test_triangles3d_equal_brute_force_random_cube),
             FL_TEST_CASE(test_triangles3d_equal_brute_force_lattice),
             FL_TEST_CASE(test_triangles3d_equal_brute_force_cospherical),
             FL_TEST_CASE(test_triangles3d_equal_brute_force_sphere_surface),
             FL_TEST_CASE(test_triangles3d_equal_brute_force_clusters))
