/* `flintstone skin --balls` checks the mesh's topology: the skin's Euler characteristic is
 * exactly 2 chi(union of balls). The two ball sets of bench/workloads/skin.sh's generator
 * (100 balls, seeds 2 and 6) on which the graded grid of grade 1.5 cuts a neck (Euler 24 and
 * 34, docs/skin.md) must end, by the default's retries, with euler == euler_expected, and
 * euler_expected must be twice the alpha-complex oracle's (skin_oracle.h, independent of
 * src/skin) while the written mesh's Euler characteristic is euler; a grid forced too coarse
 * must say topology_ok false with a warning. */
#include <math.h>
#include <stdint.h>

#include "cli/cli_run.h"
#include "fl_test.h"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function" /* the oracle's skin-function half */
#include "skin_oracle.h"
#pragma GCC diagnostic pop

/* The workload's generator is an awk program (mawk: srand(seed) is srandom(seed), rand() is
 * random() / (2^31 - 1)). This is that generator, the additive feedback generator of degree 31
 * behind random(): x_i = 16807 x_(i-1) mod (2^31 - 1) for the seed words, then
 * x_i = x_(i-31) + x_(i-3) mod 2^32, output x_i >> 1 after 310 discarded values. */
typedef struct afg {
    uint32_t ring[34];
    int pos;
} afg;

static void afg_seed(afg *g, uint32_t seed)
{
    int32_t r[34];
    r[0] = (int32_t)(seed ? seed : 1);
    for (int i = 1; i < 31; i++) {
        int64_t v = (16807 * (int64_t)r[i - 1]) % 2147483647;
        if (v < 0) v += 2147483647;
        r[i] = (int32_t)v;
    }
    for (int i = 31; i < 34; i++)
        r[i] = r[i - 31];
    for (int i = 0; i < 34; i++)
        g->ring[i] = (uint32_t)r[i];
    g->pos = 34;
    for (int i = 0; i < 310; i++) { /* discarded */
        uint32_t v = g->ring[(g->pos - 31) % 34] + g->ring[(g->pos - 3) % 34];
        g->ring[g->pos % 34] = v;
        g->pos++;
    }
}

static double afg_rand(afg *g)
{
    uint32_t v = g->ring[(g->pos - 31) % 34] + g->ring[(g->pos - 3) % 34];
    g->ring[g->pos % 34] = v;
    g->pos++;
    return (double)(v >> 1) / 2147483647.0;
}

/* skin.sh's gen_random N SEED into path: centres in [0, 2 N^(1/3)]^3, radii in [0.6, 1.2]. */
static void write_random_set(const char *path, int n, uint32_t seed)
{
    afg g;
    afg_seed(&g, seed);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return;
    double s = 2 * pow(n, 1.0 / 3);
    for (int i = 0; i < n; i++) {
        double r = 0.6 + 0.6 * afg_rand(&g);
        double x = s * afg_rand(&g), y = s * afg_rand(&g), z = s * afg_rand(&g);
        fprintf(f, "%.9f %.9f %.9f %.9f\n", x, y, z, r * r);
    }
    fclose(f);
}

static long long json_int(const char *out, const char *key)
{
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\":", key);
    const char *p = strstr(out, pat);
    CHECK_MSG(p != NULL, "no %s in %s", key, out);
    return p ? strtoll(p + strlen(pat), NULL, 10) : -999999;
}

/* 2 chi(union) by the oracle, and the Euler characteristic of the mesh file. */
static long long oracle_expected(const char *balls_path)
{
    fl_balls b;
    fl_error err;
    CHECK_STATUS(fl_read_balls(balls_path, &b, &err), FL_OK, &err);
    int ok;
    long long chi = euler_union_oracle(b.xyzw, b.count, &ok);
    CHECK(ok);
    fl_balls_free(&b);
    return 2 * chi;
}

/* b0 + b2 of the union: b0 by brute force (union-find of overlapping balls, which must agree
 * with fl_balls_union_betti's), b2 from fl_balls_union_betti (seed 58 has one cavity) */
static long long expected_components(const char *balls_path)
{
    fl_balls b;
    fl_error err;
    CHECK_STATUS(fl_read_balls(balls_path, &b, &err), FL_OK, &err);
    long long betti[3];
    CHECK_STATUS(fl_balls_union_betti(b.xyzw, b.count, betti, &err), FL_OK, &err);
    size_t n = b.count;
    size_t *parent = malloc(n * sizeof *parent);
    CHECK(parent != NULL);
    for (size_t i = 0; i < n; i++)
        parent[i] = i;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < i; j++) {
            const double *p = b.xyzw + 4 * i, *q = b.xyzw + 4 * j;
            double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                        (p[2] - q[2]) * (p[2] - q[2]);
            double r = sqrt(p[3]) + sqrt(q[3]);
            if (d2 < r * r) {
                size_t a = i, c = j;
                while (parent[a] != a)
                    a = parent[a];
                while (parent[c] != c)
                    c = parent[c];
                parent[a] = c;
            }
        }
    long long count = 0;
    for (size_t i = 0; i < n; i++)
        count += parent[i] == i;
    free(parent);
    fl_balls_free(&b);
    CHECK_MSG(betti[0] == count, "b0 %lld, overlap graph %lld", betti[0], count);
    return count + betti[2];
}

/* The Euler characteristic of the mesh file (closed and manifold checked), and its number of
 * components into *components when non-NULL. */
static long long mesh_file_euler(const char *path, long long *components)
{
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(fl_read_mesh(path, &m, &err), FL_OK, &err);
    fl_mesh_report rep;
    fl_mesh_check_options co = {0};
    co.skip_self_intersections = 1;
    CHECK_STATUS(fl_mesh_check(&m, &co, &rep, &err), FL_OK, &err);
    CHECK(rep.closed && rep.manifold);
    long long e = rep.euler;
    if (components) *components = (long long)rep.components;
    fl_mesh_report_free(&rep);
    fl_mesh_free(&m);
    return e;
}

/* The default on awk seeds 2, 6, 58 and 43 (100 balls): before round 16 grade 1.5 was wrong
 * on 2 and 6 (Euler 24 and 34), and the critical foci of the graded grid (skin_graded.c) make
 * it right at the first attempt; 58 (Euler 20, a missed cavity) is right since the balls'
 * centres are foci too (round 17); on 43 grade 1.5 makes a false handle (Euler 24, below), which
 * the default's local repair removes in its first attempt. */
static void test_cli_skin_default_retries_until_the_euler_matches_on_the_bad_sets(void)
{
    static const uint32_t seeds[4] = {2, 6, 58, 43};
    static const int attempts[4] = {1, 1, 1, 1}, repairs[4] = {0, 0, 0, 1};
    for (int k = 0; k < 4; k++) {
        write_random_set("skin_check.xyzw", 100, seeds[k]);
        long long expected = oracle_expected("skin_check.xyzw");
        cli_result r;
        CHECK_EQ_INT(cli_run(&r, "skin --balls skin_check.xyzw -o skin_check.off --json"), 0);
        CHECK_MSG(strstr(r.out, "\"topology_ok\":true") != NULL, "seed %u: %s", seeds[k], r.out);
        CHECK_EQ_INT(json_int(r.out, "euler_expected"), expected);
        CHECK_EQ_INT(json_int(r.out, "euler"), expected);
        long long comps = expected_components("skin_check.xyzw"), file_comps = -1;
        CHECK_EQ_INT(mesh_file_euler("skin_check.off", &file_comps), expected);
        CHECK_EQ_INT(json_int(r.out, "components_expected"), comps);
        CHECK_EQ_INT(json_int(r.out, "components"), comps);
        CHECK_EQ_INT(file_comps, comps);
        CHECK_MSG(json_int(r.out, "attempts") == attempts[k], "seed %u: %s", seeds[k], r.out);
        CHECK_MSG(json_int(r.out, "repairs") == repairs[k], "seed %u: %s", seeds[k], r.out);
        CHECK_MSG(strstr(r.err, "warning") == NULL, "seed %u: %s", seeds[k], r.err);
    }
    remove("skin_check.off");
    remove("skin_check.xyzw");
}

/* --repair on the sets where one graded mesh has a false handle: awk seed 43 at grade 1.5 and
 * seed 80 at grade 2.2 come out with Euler 2 below the oracle's in the right number of
 * components; with --repair 3 the grid is refined locally (repairs >= 1) and the written mesh
 * has the oracle's Euler characteristic and components. */
static void test_cli_skin_repair_removes_a_false_handle(void)
{
    static const uint32_t seeds[2] = {43, 80};
    static const char *grades[2] = {"1.5", "2.2"};
    for (int k = 0; k < 2; k++) {
        write_random_set("skin_repair.xyzw", 100, seeds[k]);
        long long expected = oracle_expected("skin_repair.xyzw");
        long long comps = expected_components("skin_repair.xyzw");
        char cmd[160];
        cli_result r;
        snprintf(cmd, sizeof cmd, "skin --balls skin_repair.xyzw --grade %s --json", grades[k]);
        CHECK_EQ_INT(cli_run(&r, cmd), 0);
        CHECK_MSG(json_int(r.out, "euler") == expected - 2, "seed %u: %s", seeds[k], r.out);
        CHECK_EQ_INT(json_int(r.out, "components"), comps);
        CHECK_EQ_INT(json_int(r.out, "repairs"), 0);
        snprintf(cmd, sizeof cmd,
                 "skin --balls skin_repair.xyzw --grade %s --repair 3 -o skin_repair.off --json",
                 grades[k]);
        CHECK_EQ_INT(cli_run(&r, cmd), 0);
        CHECK_MSG(strstr(r.out, "\"topology_ok\":true") != NULL, "seed %u: %s", seeds[k], r.out);
        CHECK_MSG(json_int(r.out, "repairs") >= 1, "seed %u: %s", seeds[k], r.out);
        long long file_comps = -1;
        CHECK_EQ_INT(mesh_file_euler("skin_repair.off", &file_comps), expected);
        CHECK_EQ_INT(file_comps, comps);
    }
    cli_result r;
    CHECK_EQ_INT(cli_run(&r, "skin --balls skin_repair.xyzw --grade 2 --repair -1"), 1);
    CHECK(strstr(r.err, "--repair") != NULL);
    remove("skin_repair.off");
    remove("skin_repair.xyzw");
}

/* Grade 8 on seed 2 makes a false handle (Euler 20 for 22; grades up to 6 are right since the
 * critical foci, round 16-17), and --grade alone does not repair. */
static void test_cli_skin_too_coarse_grid_reports_wrong_topology_with_a_warning(void)
{
    write_random_set("skin_coarse.xyzw", 100, 2);
    long long expected = oracle_expected("skin_coarse.xyzw");
    cli_result r;
    CHECK_EQ_INT(cli_run(&r, "skin --balls skin_coarse.xyzw --grade 8 -o skin_coarse.off --json"),
                 0);
    CHECK_MSG(strstr(r.out, "\"topology_ok\":false") != NULL, "%s", r.out);
    CHECK_EQ_INT(json_int(r.out, "attempts"), 1);
    CHECK_EQ_INT(json_int(r.out, "euler_expected"), expected);
    long long euler = json_int(r.out, "euler");
    CHECK(euler != expected);
    CHECK_EQ_INT(mesh_file_euler("skin_coarse.off", NULL), euler); /* the mesh is written anyway */
    CHECK_MSG(strstr(r.err, "warning") != NULL, "%s", r.err);
    /* a cell given: one uniform mesh, checked too (grade 0) */
    CHECK_EQ_INT(cli_run(&r, "skin --balls skin_coarse.xyzw --cell 0.5 --json"), 0);
    CHECK_EQ_INT(json_int(r.out, "attempts"), 1);
    CHECK_MSG(strstr(r.out, "\"grade\":0") != NULL, "%s", r.out);
    CHECK_EQ_INT(json_int(r.out, "euler_expected"), expected);
    int ok = strstr(r.out, "\"topology_ok\":true") != NULL;
    CHECK_EQ_INT(ok, json_int(r.out, "euler") == expected);
    CHECK_EQ_INT(strstr(r.err, "warning") == NULL, ok);
    remove("skin_coarse.off");
    remove("skin_coarse.xyzw");
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_cli_skin_default_retries_until_the_euler_matches_on_the_bad_sets),
        FL_TEST_CASE(test_cli_skin_too_coarse_grid_reports_wrong_topology_with_a_warning),
        FL_TEST_CASE(test_cli_skin_repair_removes_a_false_handle),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}
