/* Witness reuse in the 3D shortest-edge search (src/graphs/gamma3_edges.c, docs/gamma.md
 * "Round 11: witness reuse"): the pairs go in kd order and each pair first tests the points
 * that killed the bins of earlier dropped pairs. A pair dropped that way must be no accepted
 * triangle's shortest edge, so the default search must give, bit for bit (triangles and
 * (c0', c1') doubles), the triangles of the search without witnesses (GAMMA3_NO_WITNESS, the
 * round-10 path), of the plain ring scan (GAMMA3_PLAIN_SCAN) and, where affordable, of the
 * Theorem 3.1 brute force, on random, clustered and near-sphere sets; and the counters must
 * show that the witnesses dropped pairs. */
#include "gamma_oracle.h"

#include "gamma3_test.h"

enum { RANDOM, CLUSTERS, SPHERE };

static void make_points(int kind, size_t n, unsigned long long seed, double *p)
{
    static const double centres[4][3] = {{0, 0, 0}, {3, 0, 0}, {0, 2, 1}, {1, 1, 4}};
    for (size_t i = 0; i < n; i++) {
        if (kind == SPHERE) {
            gamma3_test_sphere_point(&seed, 0.05, p + 3 * i);
            continue;
        }
        for (int k = 0; k < 3; k++) {
            double u = fl_test_rand01(&seed);
            p[3 * i + k] = kind == RANDOM ? u
                                          : centres[i % 4][k] + (0.1 + 0.2 * (double)(i % 4)) * u;
        }
    }
}

/* Default (witnesses) against the round-10 path, the plain scan and, when `brute`, the brute
 * force; returns the number of pairs the witnesses dropped. */
static size_t compare(const double *p, size_t n, double kappa, int brute, const char *what)
{
    gamma3_stats wit, none, plain;
    fl_graph a = gamma3_test_search(p, n, kappa, GAMMA3_ALL_PAIRS, &wit);
    fl_graph b = gamma3_test_search(p, n, kappa, GAMMA3_ALL_PAIRS | GAMMA3_NO_WITNESS, &none);
    fl_graph c = gamma3_test_search(p, n, kappa, GAMMA3_ALL_PAIRS | GAMMA3_PLAIN_SCAN, &plain);
    CHECK_MSG(gamma3_test_same(&a, &b), "%s n %zu kappa %g: witnesses %zu vs none %zu triangles",
              what, n, kappa, a.simplex_count, b.simplex_count);
    CHECK_MSG(gamma3_test_same(&a, &c), "%s n %zu kappa %g: witnesses %zu vs plain %zu triangles",
              what, n, kappa, a.simplex_count, c.simplex_count);
    CHECK(a.simplex_count > 0);
    CHECK_EQ_INT((long long)none.witness_dropped, 0);
    CHECK_EQ_INT((long long)none.witness_visits, 0);
    CHECK_EQ_INT((long long)plain.witness_visits, 0);
    /* Every pair is dropped by exactly one test or scanned. */
    CHECK_EQ_INT((long long)(wit.witness_dropped + wit.quick_dropped + wit.scan_dropped +
                             wit.scan_kept),
                 (long long)(n * (n - 1) / 2));
    if (brute) {
        fl_graph d = gamma3_test_brute(p, n, kappa);
        CHECK_MSG(gamma3_test_same(&a, &d), "%s n %zu: witnesses %zu vs brute force %zu triangles",
                  what, n, a.simplex_count, d.simplex_count);
        fl_graph_free(&d);
    }
    fl_graph_free(&a);
    fl_graph_free(&b);
    fl_graph_free(&c);
    return wit.witness_dropped;
}

/* Small sets of the three kinds, two kappas, against the brute force as well. */
static void test_gamma3_witness_small_sets_equal_brute_force(void)
{
    const double kappas[2] = {0.3, 0.6};
    const char *names[3] = {"random", "clusters", "sphere"};
    double p[3 * 64];
    for (int kind = RANDOM; kind <= SPHERE; kind++) {
        size_t dropped = 0, n = kind == SPHERE ? 36 : 48;
        for (int k = 0; k < 2; k++) {
            make_points(kind, n, 1100 + (unsigned long long)(10 * kind + k), p);
            dropped += compare(p, n, kappas[k], 1, names[kind]);
        }
        if (kind != SPHERE) CHECK_MSG(dropped > 0, "%s: no pair dropped by witnesses", names[kind]);
    }
}

/* Larger sets (κ = 0.5), against the round-10 path and the plain scan: here most dropped pairs
 * are dropped by the witnesses of earlier pairs. */
static void test_gamma3_witness_larger_sets_equal_plain_scan(void)
{
    const size_t sizes[3] = {200, 200, 100};
    const char *names[3] = {"random", "clusters", "sphere"};
    double *p = malloc(3 * 200 * sizeof *p);
    for (int kind = RANDOM; kind <= SPHERE; kind++) {
        size_t n = sizes[kind];
        make_points(kind, n, 1200 + (unsigned long long)kind, p);
        size_t dropped = compare(p, n, 0.5, 0, names[kind]);
        if (kind == RANDOM) CHECK_MSG(dropped > n * (n - 1) / 20, "random: %zu dropped", dropped);
        if (kind == CLUSTERS) CHECK(dropped > 0);
    }
    free(p);
}

/* The witness path also runs under the cell-pair recursion (another pair order). */
static void test_gamma3_witness_cell_pair_order(void)
{
    double p[3 * 150];
    make_points(RANDOM, 150, 1300, p);
    gamma3_stats cells, none;
    fl_graph a = gamma3_test_search(p, 150, 0.5, GAMMA3_CELL_PAIRS, &cells);
    fl_graph b = gamma3_test_search(p, 150, 0.5, GAMMA3_ALL_PAIRS | GAMMA3_NO_WITNESS, &none);
    CHECK(gamma3_test_same(&a, &b));
    CHECK(cells.witness_dropped > 0);
    fl_graph_free(&a);
    fl_graph_free(&b);
}

FL_TEST_MAIN(FL_TEST_CASE(test_gamma3_witness_small_sets_equal_brute_force),
             FL_TEST_CASE(test_gamma3_witness_larger_sets_equal_plain_scan),
             FL_TEST_CASE(test_gamma3_witness_cell_pair_order))
