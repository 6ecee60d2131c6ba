/* γ-graphs against Definitions 3.1-3.3 evaluated literally, and the parameter lemmas of §3.5. */
#include "gamma_oracle.h"

static const double grid_c[] = {-1, -0.95, -0.7, -0.4, -0.15, 0, 0.15, 0.4, 0.7, 0.95, 1};
#define NC (sizeof grid_c / sizeof grid_c[0])

static fl_graph build(const double *p, size_t n, int dim, int range, const double *c)
{
    fl_gamma_params gp = {range, {c[0], c[1], range ? c[2] : 0, range ? c[3] : 0}};
    fl_graph g;
    fl_error err;
    CHECK_STATUS(fl_gamma_graph(p, n, dim, &gp, NULL, &g, &err), FL_OK, &err);
    return g;
}

/* Every simplex of a random set, for every (c0,c1) pair of the grid: the graph holds the simplex
 * exactly when one of its literal N_γ(c0,c1) is empty (Def. 3.2). */
static void check_fixed_against_definition(int dim, size_t n, unsigned long long seed)
{
    double *p = oracle_random_points(n, dim, seed);
    int mismatches = 0;
    for (size_t a = 0; a < NC; a++)
        for (size_t b = 0; b < NC; b++) {
            double c[2] = {grid_c[a], grid_c[b]};
            if (fabs(c[0]) > fabs(c[1])) continue;
            fl_graph g = build(p, n, dim, 0, c);
            uint32_t s[3];
            for (s[0] = 0; s[0] < n; s[0]++)
                for (s[1] = s[0] + 1; s[1] < n; s[1]++)
                    for (s[2] = dim == 3 ? s[1] + 1 : 0; dim == 2 || s[2] < n; s[2]++) {
                        int want = oracle_gamma_empty(p, n, dim, s, c[0], c[1]);
                        if (want != oracle_graph_has(&g, s) && mismatches++ < 5)
                            fprintf(stderr, "γ(%g,%g) simplex %u %u %u: definition %d\n", c[0],
                                    c[1], s[0], s[1], dim == 3 ? s[2] : 0, want);
                        if (dim == 2) break;
                    }
            fl_graph_free(&g);
        }
    CHECK_EQ_INT(mismatches, 0);
    free(p);
}

static void test_gamma_fixed_2d_matches_definition_3_1(void)
{
    for (unsigned long long seed = 1; seed <= 4; seed++)
        check_fixed_against_definition(2, 14, seed);
}

static void test_gamma_fixed_3d_matches_definition_3_1(void)
{
    for (unsigned long long seed = 11; seed <= 12; seed++)
        check_fixed_against_definition(3, 9, seed);
}

/* (c0',c1') is the largest empty neighbourhood (Def. 3.3): N_γ(c0',c1') is empty (checked a hair
 * inside), and growing either parameter a little makes it non-empty. */
static void check_params_are_largest(int dim, size_t n, unsigned long long seed)
{
    double *p = oracle_random_points(n, dim, seed);
    const double eps = 1e-7;
    int bad = 0, checked = 0;
    uint32_t s[3] = {0, 1, 2};
    for (s[0] = 0; s[0] < n; s[0]++)
        for (s[1] = s[0] + 1; s[1] < n; s[1]++)
            for (s[2] = dim == 3 ? s[1] + 1 : 0; dim == 2 || s[2] < n; s[2]++) {
                double c0, c1;
                CHECK_EQ_INT(fl_gamma_simplex_params(p, n, dim, s, &c0, &c1), 1);
                CHECK(fabs(c0) <= fabs(c1) && fabs(c1) <= 1);
                double i0 = c0 > -1 ? c0 - eps : c0, i1 = c1 > -1 ? c1 - eps : c1;
                if (fabs(i0) > fabs(i1)) i0 = c0 < 0 ? -fabs(i1) : fabs(i1);
                if (!oracle_gamma_empty(p, n, dim, s, i0, i1) && bad++ < 5)
                    fprintf(stderr, "simplex %u %u: N(%g,%g) not empty\n", s[0], s[1], c0, c1);
                if (c1 + 1e-4 <= 1 && oracle_gamma_empty(p, n, dim, s, c0, c1 + 1e-4) && bad++ < 5)
                    fprintf(stderr, "simplex %u %u: N(%g,%g+) empty\n", s[0], s[1], c0, c1);
                if (fabs(c0 + 1e-4) <= fabs(c1) &&
                    oracle_gamma_empty(p, n, dim, s, c0 + 1e-4, c1) && bad++ < 5)
                    fprintf(stderr, "simplex %u %u: N(%g+,%g) empty\n", s[0], s[1], c0, c1);
                checked++;
                if (dim == 2) break;
            }
    CHECK(checked > 0);
    CHECK_EQ_INT(bad, 0);
    free(p);
}

static void test_gamma_params_are_the_largest_empty_neighbourhood(void)
{
    check_params_are_largest(2, 16, 21);
    check_params_are_largest(2, 16, 22);
    check_params_are_largest(3, 9, 23);
}

/* Lemma 3.1 (c1 >= 0): γ(c0,c1) = γ([c0,1],[c1,1]); Lemma 3.2 (c1 < 0):
 * γ(c0,c1) = γ([c0,1],[c1,1]) ∪ γ([c1,1],[|c0|,1]). The left side is built from the literal
 * definition so the lemma is checked, not assumed. */
static void check_lemmas_3_1_and_3_2(int dim, size_t n, unsigned long long seed)
{
    double *p = oracle_random_points(n, dim, seed);
    int bad = 0;
    for (size_t a = 0; a < NC; a++)
        for (size_t b = 0; b < NC; b++) {
            double c0 = grid_c[a], c1 = grid_c[b];
            if (fabs(c0) > fabs(c1)) continue;
            double r1[4] = {c0, 1, c1, 1}, r2[4] = {c1, 1, fabs(c0), 1};
            fl_graph g1 = build(p, n, dim, 1, r1), g2 = build(p, n, dim, 1, r2);
            uint32_t s[3] = {0, 1, 2};
            for (s[0] = 0; s[0] < n; s[0]++)
                for (s[1] = s[0] + 1; s[1] < n; s[1]++)
                    for (s[2] = dim == 3 ? s[1] + 1 : 0; dim == 2 || s[2] < n; s[2]++) {
                        int lhs = oracle_gamma_empty(p, n, dim, s, c0, c1);
                        int rhs = oracle_graph_has(&g1, s) || (c1 < 0 && oracle_graph_has(&g2, s));
                        bad += lhs != rhs;
                        if (dim == 2) break;
                    }
            fl_graph_free(&g1);
            fl_graph_free(&g2);
        }
    CHECK_EQ_INT(bad, 0);
    free(p);
}

static void test_gamma_lemmas_3_1_and_3_2_on_random_sets(void)
{
    check_lemmas_3_1_and_3_2(2, 13, 31);
    check_lemmas_3_1_and_3_2(3, 8, 32);
}

/* Lemma 3.3: nested parameter intervals give nested graphs. */
static void test_gamma_lemma_3_3_nested_ranges_nest(void)
{
    unsigned long long seed = 41;
    for (int dim = 2; dim <= 3; dim++) {
        double *p = oracle_random_points(dim == 2 ? 30 : 12, dim, seed++);
        size_t n = dim == 2 ? 30 : 12;
        for (int trial = 0; trial < 30; trial++) {
            double c[4], d[4];
            for (int i = 0; i < 4; i += 2) {
                double x = 2 * fl_test_rand01(&seed) - 1, y = 2 * fl_test_rand01(&seed) - 1;
                c[i] = fmin(x, y);
                c[i + 1] = fmax(x, y);
                d[i] = c[i] - fl_test_rand01(&seed) * (c[i] + 1);
                d[i + 1] = c[i + 1] + fl_test_rand01(&seed) * (1 - c[i + 1]);
            }
            fl_graph a = build(p, n, dim, 1, c), b = build(p, n, dim, 1, d);
            CHECK(oracle_graph_subset(&a, &b));
            fl_graph_free(&a);
            fl_graph_free(&b);
        }
        free(p);
    }
}

/* A point on the open edge lies in every neighbourhood (Def. 3.1: the open simplex is always
 * part of it), so that edge has no largest empty neighbourhood; bad arguments are refused. */
static void test_simplex_params_of_a_blocked_edge_and_bad_arguments(void)
{
    const double p[8] = {0, 0, 1, 0, 2, 0, 0, 1};
    uint32_t blocked[2] = {0, 2}, hull[2] = {0, 1}, same[2] = {1, 1}, outside[2] = {0, 4};
    double c0 = 5, c1 = 5;
    CHECK_EQ_INT(fl_gamma_simplex_params(p, 4, 2, blocked, &c0, &c1), 0);
    CHECK_EQ_INT(fl_gamma_simplex_params(p, 4, 2, same, &c0, &c1), -1);
    CHECK_EQ_INT(fl_gamma_simplex_params(p, 4, 2, outside, &c0, &c1), -1);
    /* Edge 0-1: every point on or above the x axis, point 2 on the line beyond the edge: the
     * lower half-plane is empty (c1' = 1), the upper side's witness is point 3, whose circle
     * through (0,0),(1,0),(0,1) has centre (0.5,0.5): r = 0.5, t = 0.5, |c| = 1 - 1/sqrt(2),
     * centre on the other side from the half-space, so c0' = +|c|. */
    CHECK_EQ_INT(fl_gamma_simplex_params(p, 4, 2, hull, &c0, &c1), 1);
    CHECK_NEAR(c1, 1.0, 0);
    CHECK_NEAR(c0, 1 - 1 / sqrt(2.0), 1e-15);
}

static int cancel_at_once(void *user, const char *stage, double fraction)
{
    (void)stage;
    (void)fraction;
    ++*(int *)user;
    return 1;
}

static void test_progress_callback_cancels_the_brute_force_and_lens_search(void)
{
    double *p = oracle_random_points(50, 2, 77);
    int calls = 0;
    fl_graph_options opt = {FL_GAMMA_BRUTE_FORCE, 0, cancel_at_once, &calls};
    fl_gamma_params gp = {1, {-1, 1, -0.5, -0.1}};
    fl_graph g;
    fl_error err;
    CHECK_STATUS(fl_gamma_graph(p, 50, 2, &gp, &opt, &g, &err), FL_ERR_ALGORITHM, &err);
    opt.method = FL_GAMMA_AUTO;
    CHECK_STATUS(fl_gamma_graph(p, 50, 2, &gp, &opt, &g, &err), FL_ERR_ALGORITHM, &err);
    CHECK(calls == 2 && g.simplices == NULL);
    free(p);
}

FL_TEST_MAIN(FL_TEST_CASE(test_simplex_params_of_a_blocked_edge_and_bad_arguments),
             FL_TEST_CASE(test_progress_callback_cancels_the_brute_force_and_lens_search),
             FL_TEST_CASE(test_gamma_fixed_2d_matches_definition_3_1),
             FL_TEST_CASE(test_gamma_fixed_3d_matches_definition_3_1),
             FL_TEST_CASE(test_gamma_params_are_the_largest_empty_neighbourhood),
             FL_TEST_CASE(test_gamma_lemmas_3_1_and_3_2_on_random_sets),
             FL_TEST_CASE(test_gamma_lemma_3_3_nested_ranges_nest))
