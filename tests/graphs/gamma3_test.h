/* Shared by the tests of the internal 3D non-Delaunay search (gamma3_*.c): the search run as a
 * graph, graph equality including the (c0', c1') doubles, and points near the unit sphere. */
#ifndef FL_TESTS_GAMMA3_TEST_H
#define FL_TESTS_GAMMA3_TEST_H

#include <math.h>
#include <string.h>

#include "gamma_oracle.h"
#include "graphs/gamma3_search.h"

/* Non-Delaunay triangles with c1' in [-kappa, 0) through gamma3_edge_triangles_with. */
static inline fl_graph gamma3_test_search(const double *p, size_t n, double kappa,
                                          gamma3_pairs how, gamma3_stats *st)
{
    fl_error err;
    graph_grid g;
    CHECK_STATUS(graph_grid_build(&g, p, n, 3, &err), FL_OK, &err);
    fl_gamma_params gp = {1, {-1, 1, -kappa, -1e-300}};
    graph_builder b;
    graph_builder_init(&b, 3, 3, n);
    memset(st, 0, sizeof *st);
    CHECK_STATUS(gamma3_edge_triangles_with(&g, &gp, kappa, NULL, how, &b, st, &err), FL_OK,
                 &err);
    fl_graph out;
    CHECK_STATUS(graph_builder_finish(&b, 1, &out, &err), FL_OK, &err);
    graph_builder_free(&b);
    graph_grid_free(&g);
    return out;
}

/* The same graph by the brute force (the oracle of Theorem 3.1). */
static inline fl_graph gamma3_test_brute(const double *p, size_t n, double kappa)
{
    fl_gamma_params gp = {1, {-1, 1, -kappa, -1e-300}};
    fl_graph_options slow = {FL_GAMMA_BRUTE_FORCE, 1, NULL, NULL};
    fl_graph out;
    fl_error err;
    CHECK_STATUS(fl_gamma_graph(p, n, 3, &gp, &slow, &out, &err), FL_OK, &err);
    return out;
}

/* The same triangles with bit-identical (c0', c1'). */
static inline int gamma3_test_same(const fl_graph *a, const fl_graph *b)
{
    int same = oracle_graph_equal(a, b);
    for (size_t i = 0; same && i < 2 * a->simplex_count; i++)
        same = a->params[i] == b->params[i];
    return same;
}

/* A random direction (rejection in the cube) at radius 1 + jitter * u, u uniform in [-1, 1]. */
static inline void gamma3_test_sphere_point(unsigned long long *seed, double jitter, double *out)
{
    double q[3], r2;
    do {
        r2 = 0;
        for (int k = 0; k < 3; k++) {
            q[k] = 2 * fl_test_rand01(seed) - 1;
            r2 += q[k] * q[k];
        }
    } while (r2 > 1 || r2 < 0.01);
    double scale = (1 + jitter * (2 * fl_test_rand01(seed) - 1)) / sqrt(r2);
    for (int k = 0; k < 3; k++)
        out[k] = q[k] * scale;
}

#endif
