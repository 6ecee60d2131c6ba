/* The γ-graph benchmark (docs/gamma.md, "Timings"): the non-Delaunay part γ([-1,1],[-kappa,0^-])
 * (the c1 < 0 regime, only the output-sensitive search or the Theorem 3.1 brute force builds it)
 * against the brute force and against our own Delaunay triangulation of the same points.
 *
 *   gamma_bench fast|brute|dt DIM N KAPPA [SEED]
 *
 * Points: N uniform in the unit square / cube (deterministic generator, SEED default 1). One
 * timed run (the brute force takes minutes); prints
 *   RESULT mode=<m> dim=<d> n=<N> kappa=<k> cpu_s=<s> wall_s=<s> simplices=<count>
 * where simplices is the number of edges / triangles of the graph, or of triangles / tetrahedra
 * of the triangulation (mode dt). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "flintstone.h"

static double rand01(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) * (1.0 / 9007199254740992.0);
}

static double wall_now(void)
{
    struct timespec t;
    timespec_get(&t, TIME_UTC);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int fail(const char *what, const fl_error *err)
{
    char msg[1200];
    fl_error_format(err, msg, sizeof msg);
    fprintf(stderr, "gamma_bench %s: %s\n", what, msg);
    return 1;
}

int main(int argc, char **argv)
{
    if (argc < 5) {
        fprintf(stderr, "usage: gamma_bench fast|brute|dt DIM N KAPPA [SEED]\n");
        return 2;
    }
    const char *mode = argv[1];
    int dim = atoi(argv[2]);
    size_t n = (size_t)strtoull(argv[3], NULL, 10);
    double kappa = atof(argv[4]);
    unsigned long long seed = argc > 5 ? strtoull(argv[5], NULL, 10) : 1;
    if ((dim != 2 && dim != 3) || n < 4) return 2;
    double *p = malloc(n * (size_t)dim * sizeof *p);
    if (!p) return 1;
    for (size_t i = 0; i < n * (size_t)dim; i++)
        p[i] = rand01(&seed);
    fl_error err;
    size_t count = 0;
    clock_t c0 = clock();
    double w0 = wall_now();
    if (strcmp(mode, "dt") == 0) {
        if (dim == 2) {
            fl_dt2 dt;
            if (fl_dt2_build(p, n, NULL, &dt, &err) != FL_OK) return fail("dt2", &err);
            count = dt.triangle_count;
            fl_dt2_free(&dt);
        } else {
            fl_dt3 dt;
            if (fl_dt3_build(p, n, NULL, &dt, &err) != FL_OK) return fail("dt3", &err);
            count = dt.tet_count;
            fl_dt3_free(&dt);
        }
    } else {
        fl_gamma_params gp = {1, {-1, 1, -kappa, -1e-300}};
        fl_graph_options opt = {strcmp(mode, "brute") == 0 ? FL_GAMMA_BRUTE_FORCE : FL_GAMMA_AUTO,
                                0, NULL, NULL};
        fl_graph g;
        if (fl_gamma_graph(p, n, dim, &gp, &opt, &g, &err) != FL_OK) return fail("gamma", &err);
        count = g.simplex_count;
        fl_graph_free(&g);
    }
    double cpu = (double)(clock() - c0) / CLOCKS_PER_SEC, wall = wall_now() - w0;
    printf("RESULT mode=%s dim=%d n=%zu kappa=%g cpu_s=%.6f wall_s=%.6f simplices=%zu\n", mode, dim,
           n, kappa, cpu, wall, count);
    free(p);
    return 0;
}
