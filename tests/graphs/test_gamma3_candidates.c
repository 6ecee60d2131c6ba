/* Completeness of the shortest-edge candidate generation of src/graphs/gamma3_edges.c: the
 * default 3D method must give exactly the Theorem 3.1 brute force's non-Delaunay triangles and
 * the same (c0', c1') doubles on the sets where its floating filters are closest to the edge:
 * hull-heavy sets (circumcentres far outside, unbounded circumradii), points near a sphere
 * (dense output, witnesses across the set), thin slabs and near-collinear sets (long skinny
 * triangles, ill-conditioned angles around an edge), clusters and lattices (ties between edge
 * lengths, so several shortest edges), and kappa from 0.05 to 0.95 (blocking arcs from 43° to
 * 3°). The sets must produce non-Delaunay triangles for the comparison to test anything. */
#include "gamma3_test.h"

static const double kappas[] = {0.05, 0.2, 0.5, 0.8, 0.95};

/* Both methods on one parameter set; returns the number of triangles, or -1 if they differ. */
static long compare(const double *p, size_t n, const fl_gamma_params *gp, const char *what)
{
    fl_graph_options fast = {FL_GAMMA_AUTO, 1, NULL, NULL},
                     slow = {FL_GAMMA_BRUTE_FORCE, 1, NULL, NULL};
    fl_graph a, b;
    fl_error err;
    CHECK_STATUS(fl_gamma_graph(p, n, 3, gp, &fast, &a, &err), FL_OK, &err);
    CHECK_STATUS(fl_gamma_graph(p, n, 3, gp, &slow, &b, &err), FL_OK, &err);
    int same = oracle_graph_equal(&a, &b);
    for (size_t i = 0; same && i < 2 * a.simplex_count; i++)
        same = a.params[i] == b.params[i];
    if (!same)
        fprintf(stderr, "%s n %zu (%g,%g,%g,%g): default %zu vs brute force %zu triangles\n", what,
                n, gp->c[0], gp->c[1], gp->c[2], gp->c[3], a.simplex_count, b.simplex_count);
    long count = same ? (long)a.simplex_count : -1;
    fl_graph_free(&a);
    fl_graph_free(&b);
    return count;
}

static void check_set(const double *p, size_t n, const char *what)
{
    long total = 0;
    for (size_t i = 0; i < sizeof kappas / sizeof kappas[0]; i++) {
        fl_gamma_params gp = {1, {-1, 1, -kappas[i], -1e-300}};
        long c = compare(p, n, &gp, what);
        CHECK(c >= 0);
        total += c > 0 ? c : 0;
    }
    fl_gamma_params fixed = {0, {0, -0.3, 0, 0}}; /* γ(c0,c1) with c1 < 0 (Lemma 3.2) */
    CHECK(compare(p, n, &fixed, what) >= 0);
    CHECK(total > 0);
}

static void jitter_set(double *p, size_t n, double amount, unsigned long long *seed)
{
    for (size_t i = 0; i < 3 * n; i++)
        p[i] += amount * (2 * fl_test_rand01(seed) - 1);
}

static void test_gamma3_candidates_random_cube_many_seeds(void)
{
    for (unsigned long long seed = 900; seed < 905; seed++) {
        double *p = oracle_random_points(30, 3, seed);
        check_set(p, 30, "cube");
        free(p);
    }
}

/* Points on the surface of the unit cube plus a few inside: most triangles are hull triangles
 * whose lenses leave the set. */
static void test_gamma3_candidates_hull_heavy(void)
{
    for (unsigned long long seed = 910; seed < 913; seed++) {
        unsigned long long s = seed;
        double p[3 * 36];
        for (int i = 0; i < 36; i++) {
            for (int k = 0; k < 3; k++)
                p[3 * i + k] = fl_test_rand01(&s);
            if (i < 30) p[3 * i + i % 3] = (i / 3) % 2; /* on a face */
        }
        check_set(p, 36, "hull");
    }
}

/* Points within 2 % of the unit sphere: nearly every triangle has a shallow empty lens. */
static void test_gamma3_candidates_near_sphere(void)
{
    unsigned long long s = 920;
    double p[3 * 30];
    for (int i = 0; i < 30; i++)
        gamma3_test_sphere_point(&s, 0.02, p + 3 * i);
    check_set(p, 30, "sphere");
}

/* A thin slab and a thin needle: nearly coplanar / collinear sets, long skinny triangles with
 * circumradii far beyond the set, vertices close to the axes of other edges. */
static void test_gamma3_candidates_slab_and_needle(void)
{
    unsigned long long s = 930;
    double p[3 * 32];
    for (int i = 0; i < 32; i++) {
        p[3 * i] = fl_test_rand01(&s);
        p[3 * i + 1] = fl_test_rand01(&s);
        p[3 * i + 2] = 0.01 * fl_test_rand01(&s);
    }
    check_set(p, 32, "slab");
    for (int i = 0; i < 28; i++) {
        p[3 * i] = fl_test_rand01(&s);
        p[3 * i + 1] = 0.02 * fl_test_rand01(&s);
        p[3 * i + 2] = 0.02 * fl_test_rand01(&s);
    }
    check_set(p, 28, "needle");
}

/* Clusters of different sizes and a slightly jittered lattice (many near-equal edge lengths:
 * which edge is shortest is decided within rounding). */
static void test_gamma3_candidates_clusters_and_lattice(void)
{
    unsigned long long s = 940;
    double p[3 * 36];
    const double centres[4][3] = {{0, 0, 0}, {3, 0, 0}, {0, 2, 1}, {1, 1, 4}};
    for (int i = 0; i < 36; i++)
        for (int k = 0; k < 3; k++)
            p[3 * i + k] = centres[i % 4][k] + (0.05 + 0.1 * (i % 4)) * fl_test_rand01(&s);
    check_set(p, 36, "clusters");
    size_t n = 0;
    for (int x = 0; x < 4; x++)
        for (int y = 0; y < 3; y++)
            for (int z = 0; z < 3; z++, n++) {
                p[3 * n] = x;
                p[3 * n + 1] = y;
                p[3 * n + 2] = z;
            }
    jitter_set(p, n, 1e-12, &s);
    check_set(p, n, "jittered lattice");
}

/* Duplicates: exactly coincident points are bad input for both methods (FL_ERR_INPUT, nothing
 * written); near-duplicates 1e-9 apart are valid and give the shortest edges of the set, with
 * lens tests of huge |f| around them, and must still match the brute force. */
static void test_gamma3_candidates_duplicates(void)
{
    unsigned long long s = 950;
    double p[3 * 32];
    for (int i = 0; i < 24; i++)
        for (int k = 0; k < 3; k++)
            p[3 * i + k] = fl_test_rand01(&s);
    for (int i = 24; i < 32; i++)
        for (int k = 0; k < 3; k++)
            p[3 * i + k] = p[3 * (i - 24) + k] + (k == i % 3 ? 1e-9 : 0);
    check_set(p, 32, "near duplicates");
    p[3 * 31] = p[3 * 7];
    p[3 * 31 + 1] = p[3 * 7 + 1];
    p[3 * 31 + 2] = p[3 * 7 + 2]; /* point 31 == point 7 */
    fl_gamma_params gp = {1, {-1, 1, -0.5, -1e-300}};
    for (int method = 0; method < 2; method++) {
        fl_graph_options opt = {method ? FL_GAMMA_BRUTE_FORCE : FL_GAMMA_AUTO, 1, NULL, NULL};
        fl_graph g;
        fl_error err;
        memset(&g, 0, sizeof g);
        CHECK_STATUS(fl_gamma_graph(p, 32, 3, &gp, &opt, &g, &err), FL_ERR_INPUT, &err);
        CHECK(g.simplex_count == 0);
    }
}

FL_TEST_MAIN(FL_TEST_CASE(test_gamma3_candidates_random_cube_many_seeds),
             FL_TEST_CASE(test_gamma3_candidates_duplicates),
             FL_TEST_CASE(test_gamma3_candidates_hull_heavy),
             FL_TEST_CASE(test_gamma3_candidates_near_sphere),
             FL_TEST_CASE(test_gamma3_candidates_slab_and_needle),
             FL_TEST_CASE(test_gamma3_candidates_clusters_and_lattice))
