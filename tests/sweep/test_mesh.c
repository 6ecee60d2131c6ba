/* Mesh closest-point queries against brute force over every triangle (sweep_oracle.h). */
#include <stdint.h>

#include "fl_test.h"
#include "sweep/sweep_internal.h"
#include "mesh_answer_check.h"
#include "sweep_volume_check.h"
#include "sweep_work.h"

static unsigned long long rng = 0x5eedULL;

static double urand(double lo, double hi)
{
    return lo + (hi - lo) * fl_test_rand01(&rng);
}

static fl_mesh mesh_alloc(size_t nv, size_t nt)
{
    fl_mesh m = {nv, malloc(3 * nv * sizeof(double)), nt, malloc(3 * nt * sizeof(uint32_t))};
    return m;
}

/* A closed torus (R = 1, r = 0.3) of 2 nu nv triangles. */
static fl_mesh make_torus(int nu, int nv)
{
    fl_mesh m = mesh_alloc((size_t)nu * nv, 2 * (size_t)nu * nv);
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double u = 6.283185307179586 * i / nu, v = 6.283185307179586 * j / nv;
            double *p = m.xyz + 3 * ((size_t)i * nv + j);
            p[0] = (1 + 0.3 * cos(v)) * cos(u);
            p[1] = (1 + 0.3 * cos(v)) * sin(u);
            p[2] = 0.3 * sin(v);
            uint32_t a = (uint32_t)(i * nv + j), b = (uint32_t)(((i + 1) % nu) * nv + j);
            uint32_t c = (uint32_t)(((i + 1) % nu) * nv + (j + 1) % nv);
            uint32_t d = (uint32_t)(i * nv + (j + 1) % nv);
            uint32_t *t = m.tri + 6 * ((size_t)i * nv + j);
            t[0] = a, t[1] = b, t[2] = c, t[3] = a, t[4] = c, t[5] = d;
        }
    return m;
}

/* n independent random triangles of size ~size in the unit cube. */
static fl_mesh make_soup(size_t n, double size)
{
    fl_mesh m = mesh_alloc(3 * n, n);
    for (size_t t = 0; t < n; t++) {
        double c[3] = {urand(0, 1), urand(0, 1), urand(0, 1)};
        for (int k = 0; k < 3; k++) {
            for (int x = 0; x < 3; x++)
                m.xyz[9 * t + 3 * k + x] = c[x] + urand(-size, size);
            m.tri[3 * t + k] = (uint32_t)(3 * t + k);
        }
    }
    return m;
}

/* An open wavy 8x8 grid patch plus the awkward cases: a fin of three triangles on one edge
 * (non-manifold), exactly degenerate triangles (collinear, repeated vertex), a duplicated
 * vertex and a repeated triangle. */
static fl_mesh make_messy(void)
{
    const int g = 8;
    size_t nv = (size_t)g * g + 6, nt = 2 * (size_t)(g - 1) * (g - 1) + 6;
    fl_mesh m = mesh_alloc(nv, nt);
    for (int i = 0; i < g; i++)
        for (int j = 0; j < g; j++) {
            double *p = m.xyz + 3 * ((size_t)i * g + j);
            p[0] = i, p[1] = j, p[2] = 0.25 * sin(i) * cos(j);
        }
    size_t t = 0;
    for (int i = 0; i + 1 < g; i++)
        for (int j = 0; j + 1 < g; j++) {
            uint32_t a = (uint32_t)(i * g + j), b = a + (uint32_t)g, c = b + 1, d = a + 1;
            uint32_t *tt = m.tri + 3 * t;
            tt[0] = a, tt[1] = b, tt[2] = c, tt[3] = a, tt[4] = c, tt[5] = d;
            t += 2;
        }
    double extra[6][3] = {{3, 3, 2}, {3, 3, -2}, {10, 0, 0}, {12, 0, 0}, {14, 0, 0}, {0, 0, 0}};
    size_t base = (size_t)g * g;
    memcpy(m.xyz + 3 * base, extra, sizeof extra); /* vertex base+5 duplicates vertex 0 */
    uint32_t b0 = (uint32_t)base, e0 = (uint32_t)(3 * g + 3), e1 = (uint32_t)(3 * g + 4);
    uint32_t more[6][3] = {{e0, e1, b0},
                           {e0, e1, b0 + 1},
                           {b0 + 2, b0 + 3, b0 + 4},
                           {b0 + 2, b0 + 2, b0 + 3},
                           {b0 + 5, 1, (uint32_t)g},
                           {e0, e1, b0}};
    memcpy(m.tri + 3 * t, more, sizeof more);
    return m;
}

/* Checks one exact answer (mesh_answer_check.h) and that its barycentrics are a convex
 * combination. */
static void check_exact_bary(const fl_mesh *m, const double *q, const fl_closest *r)
{
    check_exact(m, q, r);
    CHECK(r->bary[0] >= 0 && r->bary[1] >= 0 && r->bary[2] >= 0);
    CHECK_NEAR(r->bary[0] + r->bary[1] + r->bary[2], 1, 1e-12);
}

/* Random queries in the box around the mesh, far away, and on the surface. */
static double *make_queries(const fl_mesh *m, size_t n)
{
    double *q = malloc(3 * n * sizeof *q), s = mesh_scale(m);
    for (size_t i = 0; i < n; i++) {
        double *p = q + 3 * i;
        if (i % 3 == 0) {
            for (int c = 0; c < 3; c++)
                p[c] = urand(-1.2 * s, 1.2 * s);
        } else if (i % 3 == 1) {
            for (int c = 0; c < 3; c++)
                p[c] = urand(-1000 * s, 1000 * s);
        } else {
            size_t t = fl_test_rand_u64(&rng) % m->triangle_count;
            double u = urand(0, 1), v = urand(0, 1 - u);
            for (int c = 0; c < 3; c++)
                p[c] = (1 - u - v) * oracle_vertex(m->xyz, m->tri, t, 0)[c] +
                       u * oracle_vertex(m->xyz, m->tri, t, 1)[c] +
                       v * oracle_vertex(m->xyz, m->tri, t, 2)[c];
        }
    }
    return q;
}

static void check_mesh_queries(const fl_mesh *m, size_t nq)
{
    fl_error err;
    fl_sweep *s = NULL;
    CHECK_STATUS(fl_sweep_build(m, NULL, &s, &err), FL_OK, &err);
    if (!s) return;
    double *q = make_queries(m, nq);
    fl_closest *r = calloc(nq, sizeof *r);
    CHECK_STATUS(fl_sweep_closest(s, q, nq, 0, r, &err), FL_OK, &err);
    for (size_t i = 0; i < nq; i++)
        check_exact_bary(m, q + 3 * i, r + i);
    free(q);
    free(r);
    fl_sweep_free(s);
}

static void test_sweep_torus_matches_brute_force(void)
{
    fl_mesh m = make_torus(40, 20);
    check_mesh_queries(&m, 300);
    fl_mesh_free(&m);
}

static void test_sweep_triangle_soup_matches_brute_force(void)
{
    fl_mesh m = make_soup(600, 0.08);
    check_mesh_queries(&m, 300);
    fl_mesh_free(&m);
    m = make_soup(1, 0.3);
    check_mesh_queries(&m, 30);
    fl_mesh_free(&m);
}

static void test_sweep_open_nonmanifold_degenerate_matches_brute_force(void)
{
    fl_mesh m = make_messy();
    check_mesh_queries(&m, 400);
    /* Queries near the degenerate triangles and on the fin. */
    double q[4][3] = {{11, 0.5, 0.1}, {13, -1, 0}, {3.5, 3.5, 1.5}, {0, 0, 0}};
    fl_sweep *s = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    for (int i = 0; i < 4 && s; i++) {
        fl_closest r;
        CHECK_STATUS(fl_sweep_closest(s, q[i], 1, 0, &r, &err), FL_OK, &err);
        check_exact_bary(&m, q[i], &r);
    }
    fl_sweep_free(s);
    fl_mesh_free(&m);
}

/* Every vertex of every triangle below a node lies within ε of the node's triangle (§4.1). */
static void test_sweep_volumes_contain_their_triangles(void)
{
    fl_mesh m = make_torus(24, 12);
    fl_sweep *s = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    if (!s) return;
    CHECK_EQ_INT(s->node_count, 2 * m.triangle_count - 1);
    check_volumes(s, &m);
    fl_sweep_free(s);
    fl_mesh_free(&m);
}

/* A random walk of small steps among separated triangles: exact at every step, and the
 * coherence ball of §3.3 answers some steps in constant time. (On a closed mesh the answer is
 * often a vertex shared by several equidistant triangles, where §3.3 gives no ball.) */
static void test_sweep_random_walk_uses_coherence_ball(void)
{
    fl_mesh m = make_soup(200, 0.05);
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    double q[3] = {0.5, 0.5, 0.5};
    int reused = 0;
    for (int step = 0; step < 400 && cur; step++) {
        for (int c = 0; c < 3; c++)
            q[c] += urand(-0.002, 0.002);
        fl_closest r;
        CHECK_STATUS(fl_sweep_cursor_closest(cur, q, 0, &r, &err), FL_OK, &err);
        check_exact_bary(&m, q, &r);
        reused += r.reused;
    }
    CHECK_MSG(reused > 0, "none of 400 steps reused the ball (%d)", reused);
    /* Among separated triangles the nearest one is unique, so the ball has a positive radius
     * and the same query again is answered from it. */
    for (int i = 0; i < 100 && cur; i++) {
        double p[3] = {urand(0, 1), urand(0, 1), urand(0, 1)};
        fl_closest r1, r2;
        CHECK_STATUS(fl_sweep_cursor_closest(cur, p, 0, &r1, &err), FL_OK, &err);
        CHECK_STATUS(fl_sweep_cursor_closest(cur, p, 0, &r2, &err), FL_OK, &err);
        CHECK(r2.reused && r2.visited == 1 && r2.element == r1.element);
        CHECK(r2.distance == r1.distance);
    }
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
    fl_mesh_free(&m);
}

/* §5.1: along a slow walk over a closed mesh the cursor keeps its queue, widening the
 * intervals by each move; every answer (exact, and with a tolerance the interval) stays
 * correct, and the walk costs under half the work (distances + box distances, sweep_work.h) of
 * independent queries. */
static void test_sweep_dynamic_walk_stays_exact_and_is_cheaper(void)
{
    fl_mesh m = make_torus(40, 20);
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    double q[3] = {1.37, 0.23, 0.41};
    size_t walk_cost = 0, fresh_cost = 0;
    for (int step = 0; step < 300 && cur; step++) {
        for (int c = 0; c < 3; c++)
            q[c] += urand(-0.003, 0.003);
        fl_closest r, fresh;
        double tol = step % 3 == 2 ? 0.01 : 0;
        size_t boxes = fl_sweep_cursor_box_tests(cur);
        CHECK_STATUS(fl_sweep_cursor_closest(cur, q, tol, &r, &err), FL_OK, &err);
        if (r.exact) {
            check_exact_bary(&m, q, &r);
        } else {
            double bf = (double)brute_distance(&m, q);
            CHECK(r.lower <= bf + 1e-12 && bf <= r.upper + 1e-12 && r.upper - r.lower <= tol);
        }
        if (tol > 0) continue;
        walk_cost += r.visited + fl_sweep_cursor_box_tests(cur) - boxes;
        fresh_cost += sweep_fresh_work(s, NULL, q, &fresh);
        CHECK_NEAR(fresh.distance, r.distance, 1e-13);
    }
    CHECK_MSG(2 * walk_cost < fresh_cost, "walk %zu vs fresh %zu work", walk_cost, fresh_cost);
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
    fl_mesh_free(&m);
}

/* §3.2 early stop: the interval brackets the true distance and is narrower than asked. */
static void test_sweep_tolerance_interval_brackets_distance(void)
{
    fl_mesh m = make_torus(40, 20);
    fl_sweep *s = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    double *q = make_queries(&m, 200);
    const double tols[3] = {1e-3, 0.05, 1.0};
    int inexact = 0;
    for (int k = 0; k < 3 && s; k++)
        for (size_t i = 0; i < 200; i++) {
            fl_closest r;
            CHECK_STATUS(fl_sweep_closest(s, q + 3 * i, 1, tols[k], &r, &err), FL_OK, &err);
            double bf = (double)brute_distance(&m, q + 3 * i), slack = 1e-12 * (1 + fabs(q[3 * i]));
            CHECK(r.lower <= bf + slack && bf <= r.upper + slack * 1e3);
            CHECK(r.upper - r.lower <= tols[k]);
            if (r.exact) CHECK_NEAR(r.distance, bf, slack * 1e3);
            inexact += !r.exact;
        }
    CHECK(inexact > 0);
    free(q);
    fl_sweep_free(s);
    fl_mesh_free(&m);
}

static int cmp_ld(const void *a, const void *b)
{
    ld x = *(const ld *)a, y = *(const ld *)b;
    return x < y ? -1 : x > y;
}

/* §4.4: the k nearest come out in order with brute-force distances, and "within r" returns
 * exactly the triangles at distance <= r. */
static void test_sweep_knearest_and_within_match_brute_force(void)
{
    fl_mesh m = make_soup(400, 0.1);
    fl_sweep *s = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    ld *all = malloc(m.triangle_count * sizeof *all);
    uint32_t el[25];
    double dist[25];
    for (int i = 0; i < 40 && s; i++) {
        double q[3] = {urand(-0.5, 1.5), urand(-0.5, 1.5), urand(-0.5, 1.5)};
        for (size_t t = 0; t < m.triangle_count; t++)
            all[t] = oracle_mesh_element(m.xyz, m.tri, t, q);
        qsort(all, m.triangle_count, sizeof *all, cmp_ld);
        size_t found = 0, k = 1 + (size_t)i % 25;
        CHECK_STATUS(fl_sweep_knearest(s, q, k, el, dist, &found, &err), FL_OK, &err);
        CHECK_EQ_INT(found, k);
        for (size_t j = 0; j < found; j++) {
            CHECK_NEAR(dist[j], (double)all[j], 1e-12);
            CHECK_NEAR((double)oracle_mesh_element(m.xyz, m.tri, el[j], q), dist[j], 1e-12);
        }
        double r = (double)(all[k - 1] + all[k]) / 2;
        fl_sweep_hits hits;
        CHECK_STATUS(fl_sweep_within(s, q, r, &hits, &err), FL_OK, &err);
        CHECK_EQ_INT(hits.count, k);
        for (size_t j = 0; j < hits.count; j++)
            CHECK_NEAR(hits.distance[j], (double)all[j], 1e-12);
        fl_sweep_hits_free(&hits);
    }
    size_t found = 0;
    uint32_t big[500];
    double bigd[500];
    double q[3] = {0.5, 0.5, 0.5};
    CHECK_STATUS(fl_sweep_knearest(s, q, 500, big, bigd, &found, &err), FL_OK, &err);
    CHECK_EQ_INT(found, m.triangle_count);
    free(all);
    fl_sweep_free(s);
    fl_mesh_free(&m);
}

/* §4.4 on a one-triangle mesh, whose hierarchy is a single leaf (found by h-collapse2's fuzz
 * check): the distance is the point-triangle distance (it was -inf), and "within r" honours r
 * (the leaf was returned at any radius). */
static void test_sweep_knearest_and_within_on_one_triangle(void)
{
    double xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    uint32_t tri[3] = {0, 1, 2};
    fl_mesh m = {3, xyz, 1, tri};
    fl_sweep *s = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    if (!s) return;
    double q[3] = {0.25, 0.25, 2};
    double bf = (double)oracle_mesh_element(xyz, tri, 0, q);
    uint32_t el = 7;
    double d = 0;
    size_t found = 0;
    CHECK_STATUS(fl_sweep_knearest(s, q, 3, &el, &d, &found, &err), FL_OK, &err);
    CHECK_EQ_INT(found, 1);
    CHECK_EQ_INT(el, 0);
    CHECK_NEAR(d, bf, 1e-15);
    fl_sweep_hits hits;
    CHECK_STATUS(fl_sweep_within(s, q, 1.5, &hits, &err), FL_OK, &err);
    CHECK_EQ_INT(hits.count, 0);
    fl_sweep_hits_free(&hits);
    CHECK_STATUS(fl_sweep_within(s, q, 2.5, &hits, &err), FL_OK, &err);
    CHECK_EQ_INT(hits.count, 1);
    if (hits.count == 1) CHECK_NEAR(hits.distance[0], bf, 1e-15);
    fl_sweep_hits_free(&hits);
    fl_sweep_free(s);
}

static void test_sweep_rejects_bad_meshes(void)
{
    fl_error err;
    fl_sweep *s = NULL;
    double xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    uint32_t tri[3] = {0, 1, 3};
    fl_mesh m = {3, xyz, 1, tri};
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_ERR_INPUT, &err);
    CHECK(s == NULL);
    tri[2] = 2;
    xyz[4] = NAN;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_ERR_INPUT, &err);
    xyz[4] = 1e200;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_ERR_INPUT, &err);
    xyz[4] = 0;
    m.triangle_count = 0;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_sweep_build(NULL, NULL, &s, &err), FL_ERR_USAGE, &err);
    m.triangle_count = 1;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    double q[3] = {0, NAN, 0};
    fl_closest r;
    CHECK_STATUS(fl_sweep_closest(s, q, 1, 0, &r, &err), FL_ERR_USAGE, &err);
    q[1] = -1e151;
    CHECK_STATUS(fl_sweep_closest(s, q, 1, 0, &r, &err), FL_ERR_USAGE, &err);
    q[1] = 1e150; /* the largest accepted: distances stay finite */
    CHECK_STATUS(fl_sweep_closest(s, q, 1, 0, &r, &err), FL_OK, &err);
    CHECK(r.exact && r.distance == 1e150);
    q[1] = 0;
    CHECK_STATUS(fl_sweep_closest(s, q, 1, -1, &r, &err), FL_ERR_USAGE, &err);
    fl_sweep_free(s);
}

FL_TEST_MAIN(FL_TEST_CASE(test_sweep_torus_matches_brute_force),
             FL_TEST_CASE(test_sweep_triangle_soup_matches_brute_force),
             FL_TEST_CASE(test_sweep_open_nonmanifold_degenerate_matches_brute_force),
             FL_TEST_CASE(test_sweep_volumes_contain_their_triangles),
             FL_TEST_CASE(test_sweep_random_walk_uses_coherence_ball),
             FL_TEST_CASE(test_sweep_dynamic_walk_stays_exact_and_is_cheaper),
             FL_TEST_CASE(test_sweep_tolerance_interval_brackets_distance),
             FL_TEST_CASE(test_sweep_knearest_and_within_match_brute_force),
             FL_TEST_CASE(test_sweep_knearest_and_within_on_one_triangle),
             FL_TEST_CASE(test_sweep_rejects_bad_meshes))
