/* Degenerate inputs for the γ-graph and the classic graphs. Expected outcomes: specific errors
 * for empty/duplicate/NaN input; on grids, cocircular and collinear sets (where the Delaunay-
 * based fast paths meet their ties) the default method must give exactly the simplices of the
 * brute force of Theorem 3.1, which tests every simplex against every point; classic graphs
 * of collinear points are the path of consecutive points (the only empty-ball edges). */
#include "degen.h"

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

/* Default method == brute force for one parameter set. */
static void expect_same_as_brute(const char *name, const double *c, size_t n, int dim,
                                 fl_gamma_params p)
{
    fl_graph_options opt = {0};
    fl_graph fast, brute;
    fl_error err;
    fl_status st = fl_gamma_graph(c, n, dim, &p, &opt, &fast, &err);
    CHECK_MSG(st == FL_OK, "%s: %s", name, err.message);
    if (st != FL_OK) return;
    opt.method = FL_GAMMA_BRUTE_FORCE;
    st = fl_gamma_graph(c, n, dim, &p, &opt, &brute, &err);
    CHECK_MSG(st == FL_OK, "%s brute: %s", name, err.message);
    if (st == FL_OK) {
        CHECK_MSG(fast.simplex_count == brute.simplex_count, "%s (%g,%g,%g,%g): %zu vs brute %zu",
                  name, p.c[0], p.c[1], p.c[2], p.c[3], fast.simplex_count, brute.simplex_count);
        if (fast.simplex_count == brute.simplex_count)
            CHECK_MSG(memcmp(fast.simplices, brute.simplices, fast.simplex_count *
                             (size_t)fast.simplex_size * sizeof(uint32_t)) == 0,
                      "%s: simplex lists differ", name);
        fl_graph_free(&brute);
    }
    fl_graph_free(&fast);
}

static void test_gamma_failures(void)
{
    fl_gamma_params del = {1, {-1, 1, 0, 1}};
    fl_graph g;
    fl_error err;
    double dup[] = {0, 0, 1, 0, 0, 1, 1, 0};
    CHECK_FAILS(fl_gamma_graph(dup, 4, 2, &del, NULL, &g, &err), &err, FL_ERR_INPUT, "coincide");
    double nan_[] = {0, 0, 1, 0, 0, NAN};
    CHECK_FAILS(fl_gamma_graph(nan_, 3, 2, &del, NULL, &g, &err), &err, FL_ERR_INPUT,
                "non-finite");
    double inf_[] = {0, 0, 0, 1, 0, 0, 0, 1, -INFINITY};
    CHECK_FAILS(fl_gamma_graph(inf_, 3, 3, &del, NULL, &g, &err), &err, FL_ERR_INPUT,
                "non-finite");
    /* Empty, one and two points: no simplices, or the one edge. */
    double two[] = {0, 0, 3, 4};
    for (size_t n = 0; n <= 2; n++) {
        CHECK_STATUS(fl_gamma_graph(two, n, 2, &del, NULL, &g, &err), FL_OK, &err);
        CHECK_EQ_INT(g.simplex_count, n == 2 ? 1 : 0);
        fl_graph_free(&g);
    }
}

static void test_gamma_degenerate_sets(void)
{
    static const fl_gamma_params params[] = {
        {1, {-1, 1, 0, 1}},   /* Delaunay */
        {0, {0, 0, 0, 0}},    /* Gabriel */
        {0, {-1, 1, 0, 0}},   /* convex hull */
        {0, {0.5, 0.5, 0, 0}}, /* β-skeleton */
        {0, {-0.3, -0.6, 0, 0}},
        {1, {-1, 1, -0.5, 1}},
    };
    double c[3 * 64];
    char name[64];
    for (size_t k = 0; k < sizeof params / sizeof *params; k++) {
        size_t n = grid2(c, 5, 1);
        expect_same_as_brute("5x5 grid", c, n, 2, params[k]);
        n = grid2(c, 4, 1e-300);
        expect_same_as_brute("4x4 grid at 1e-300", c, n, 2, params[k]);
        n = circle12(c, 1e250);
        expect_same_as_brute("12 cocircular at 1e250", c, n, 2, params[k]);
        double line[] = {0, 0, 1, 1, 2, 2, 5, 5, -3, -3};
        expect_same_as_brute("collinear", line, 5, 2, params[k]);
        if (k < 3) { /* 3D brute force is O(n^4): small sets */
            n = grid3(c, 3, 1);
            expect_same_as_brute("3x3x3 grid", c, n, 3, params[k]);
            n = sphere30(c, 1);
            snprintf(name, sizeof name, "30 cospherical");
            expect_same_as_brute(name, c, 14, 3, params[k]); /* first 14: still cospherical */
        }
    }
}

/* Regression (found by fuzz/fuzz_graphs.c): coordinates near ±1e308 made the bucket grid's
 * extent infinite and its cell count NaN (undefined behaviour, then a huge allocation). */
static void test_gamma_extreme_extent(void)
{
    double c[] = {-1e308, -1e308, 1e308, 1e308, 1e308, -1e308, 0, 0, -1e308, 1e308};
    fl_gamma_params gab = {0, {0, 0, 0, 0}};
    expect_same_as_brute("±1e308", c, 5, 2, gab);
    fl_graph g;
    fl_error err;
    CHECK_STATUS(fl_classic_graph(c, 5, 2, FL_GRAPH_EMST, 0, &g, &err), FL_OK, &err);
    CHECK_EQ_INT(g.simplex_count, 4);
    fl_graph_free(&g);
}

/* Collinear points: Delaunay, Gabriel, RNG, EMST are all the path of consecutive points. */
static void test_classic_collinear(void)
{
    double c[] = {0, 0, 4, 2, 2, 1, -2, -1, 6, 3, 8, 4};
    uint32_t path[] = {0, 2, 1, 2, 1, 4, 3, 0, 4, 5}; /* consecutive along the line */
    for (size_t i = 0; i < 5; i++) qsort(path + 2 * i, 2, sizeof(uint32_t), cmp_u32);
    static const fl_graph_kind kinds[] = {FL_GRAPH_DELAUNAY, FL_GRAPH_GABRIEL, FL_GRAPH_RNG,
                                          FL_GRAPH_EMST};
    for (size_t k = 0; k < 4; k++) {
        fl_graph g;
        fl_error err;
        CHECK_STATUS(fl_classic_graph(c, 6, 2, kinds[k], 0, &g, &err), FL_OK, &err);
        CHECK_MSG(g.simplex_count == 5, "kind %d: %zu edges", (int)kinds[k], g.simplex_count);
        for (size_t e = 0; e < g.simplex_count && e < 5; e++) {
            int found = 0;
            for (size_t f = 0; f < 5; f++)
                found |= g.simplices[2 * e] == path[2 * f] &&
                         g.simplices[2 * e + 1] == path[2 * f + 1];
            CHECK_MSG(found, "kind %d: edge %u-%u is not consecutive", (int)kinds[k],
                      g.simplices[2 * e], g.simplices[2 * e + 1]);
        }
        fl_graph_free(&g);
    }
}

int main(void)
{
    fl_test_case cases[] = {
        FL_TEST_CASE(test_gamma_failures),
        FL_TEST_CASE(test_gamma_degenerate_sets),
        FL_TEST_CASE(test_gamma_extreme_extent),
        FL_TEST_CASE(test_classic_collinear),
    };
    return fl_test_run(cases, sizeof cases / sizeof *cases);
}
