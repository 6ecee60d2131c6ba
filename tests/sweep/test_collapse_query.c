/* Edge-collapse hierarchy queries (Guéziec §4.2-4.3, §3.2, §5.1) against brute force over every
 * triangle: random and coherent query streams on closed, open, non-manifold/degenerate meshes
 * and a soup; tolerance intervals bracket the distance; bad input is rejected. */
#include "sweep/collapse_internal.h"
#include "test_collapse_meshes.h"

static fl_sweep_collapse *build(const fl_mesh *m)
{
    fl_sweep_collapse *h = NULL;
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_build(m, NULL, &h, &err), FL_OK, &err);
    return h;
}

/* Random queries: a third near the surface, a third in the box, a third far away. */
static void random_queries(const fl_mesh *m, double *q, size_t n)
{
    double s = mesh_scale(m);
    for (size_t i = 0; i < n; i++) {
        double *p = q + 3 * i;
        if (i % 3 == 0) {
            size_t t = (size_t)(fl_test_rand01(&cm_rng) * (double)m->triangle_count);
            double a = cm_rand(0, 1), b = cm_rand(0, 1 - a);
            for (int c = 0; c < 3; c++)
                p[c] = (1 - a - b) * oracle_vertex(m->xyz, m->tri, t, 0)[c] +
                       a * oracle_vertex(m->xyz, m->tri, t, 1)[c] +
                       b * oracle_vertex(m->xyz, m->tri, t, 2)[c] + cm_rand(-0.02, 0.02) * s;
        } else {
            double r = i % 3 == 1 ? 1.3 * s : 1000 * s;
            for (int c = 0; c < 3; c++)
                p[c] = cm_rand(-r, r);
        }
    }
}

/* Exact batches (through one cursor, so resets and kept meshes mix) and fresh cursors. */
static void check_random(const fl_mesh *m, size_t n)
{
    fl_sweep_collapse *h = build(m);
    if (!h) return;
    double *q = malloc(3 * n * sizeof *q);
    fl_closest *r = malloc(n * sizeof *r);
    random_queries(m, q, n);
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_closest(h, q, n, 0.0, r, &err), FL_OK, &err);
    for (size_t i = 0; i < n; i++)
        check_exact(m, q + 3 * i, r + i);
    fl_sweep_collapse_info info;
    CHECK_STATUS(fl_sweep_collapse_info_get(h, &info, &err), FL_OK, &err);
    CHECK(info.fine_triangles == m->triangle_count);
    CHECK(info.base_triangles >= 1 && info.base_triangles <= info.triangles);
    printf("  %zu triangles: base %zu, %zu splits, %zu hierarchy triangles, %.0f B/triangle\n",
           m->triangle_count, info.base_triangles, info.splits, info.triangles,
           (double)info.bytes / (double)m->triangle_count);
    free(q);
    free(r);
    fl_sweep_collapse_free(h);
}

static void test_closed_random(void)
{
    for (int k = 0; k < 3; k++) {
        fl_mesh m = cm_noisy_torus(20 + 7 * k, 10 + 3 * k, 0.1 * k);
        check_random(&m, 300);
        cm_free(&m);
    }
}

static void test_open_random(void)
{
    fl_mesh m = cm_open_grid(20, 0.05);
    check_random(&m, 300);
    cm_free(&m);
}

static void test_messy_random(void)
{
    fl_mesh m = cm_messy(12);
    check_random(&m, 300);
    cm_free(&m);
}

/* §3.3 ball: among separated triangles the closest one is unique with a gap to the second,
 * so repeating a query (and moving it a little) through a cursor is answered from the ball,
 * exactly, with one distance; a far jump is not. */
static void test_ball(void)
{
    fl_mesh m = cm_soup(60, 0.05);
    fl_sweep_collapse *h = build(&m);
    fl_sweep_collapse_cursor *c = NULL;
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_cursor_new(h, &c, &err), FL_OK, &err);
    if (!c) return;
    size_t reused = 0;
    for (int i = 0; i < 40; i++) {
        double q[3];
        random_queries(&m, q, 1);
        fl_closest r;
        CHECK_STATUS(fl_sweep_collapse_cursor_closest(c, q, 0.0, &r, &err), FL_OK, &err);
        check_exact(&m, q, &r);
        CHECK(r.reused == 0);
        q[0] += 1e-9;
        CHECK_STATUS(fl_sweep_collapse_cursor_closest(c, q, 0.0, &r, &err), FL_OK, &err);
        check_exact(&m, q, &r);
        reused += r.reused;
        CHECK(!r.reused || r.visited == 1);
    }
    printf("  %zu of 40 nudged queries from the ball\n", reused);
    CHECK(reused >= 36);
    fl_sweep_collapse_cursor_free(c);
    fl_sweep_collapse_free(h);
    cm_free(&m);
}

static void test_soup_random(void)
{
    fl_mesh m = cm_soup(200, 0.05);
    check_random(&m, 150);
    cm_free(&m);
    fl_mesh one = cm_soup(1, 0.3);
    check_random(&one, 30);
    cm_free(&one);
}

/* A slow random walk through one cursor keeps the refined mesh (§5.1): exact at every step, and
 * cheaper than the same queries each from the base mesh. */
static void test_coherent_walk(void)
{
    fl_mesh m = cm_noisy_torus(40, 16, 0.05);
    fl_sweep_collapse *h = build(&m);
    if (!h) return;
    fl_sweep_collapse_cursor *c = NULL;
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_cursor_new(h, &c, &err), FL_OK, &err);
    double p[3] = {1.2, 0.1, 0.05}, dir[3] = {0, 0, 0};
    size_t walk_cost = 0, fresh_cost = 0, reused = 0;
    for (int i = 0; i < 400; i++) {
        for (int k = 0; k < 3; k++) {
            dir[k] = 0.9 * dir[k] + cm_rand(-0.003, 0.003);
            p[k] += dir[k];
        }
        fl_closest r, f;
        CHECK_STATUS(fl_sweep_collapse_cursor_closest(c, p, 0.0, &r, &err), FL_OK, &err);
        check_exact(&m, p, &r);
        walk_cost += r.visited;
        reused += r.reused;
        CHECK(!r.reused || r.visited == 1);
        CHECK_STATUS(fl_sweep_collapse_closest(h, p, 1, 0.0, &f, &err), FL_OK, &err);
        fresh_cost += f.visited;
        if (i % 50 == 49) { /* a tolerance query in between must bracket the distance */
            CHECK_STATUS(fl_sweep_collapse_cursor_closest(c, p, 1e-2, &r, &err), FL_OK, &err);
            double bf = (double)brute_distance(&m, p);
            CHECK(r.lower <= bf + 1e-12 && bf <= r.upper + 1e-12);
            CHECK(r.upper - r.lower <= 1e-2);
        }
    }
    printf("  walk: %zu distances through the cursor, %zu from the base mesh, %zu of 400 "
           "answers from the §3.3 ball\n", walk_cost, fresh_cost, reused);
    CHECK(2 * walk_cost < fresh_cost);
    fl_sweep_collapse_cursor_free(c);
    fl_sweep_collapse_free(h);
    cm_free(&m);
}

/* With a tolerance the interval brackets the brute-force distance and is narrow enough; some
 * queries stop early. */
static void test_tolerance(void)
{
    fl_mesh m = cm_noisy_torus(30, 12, 0.1);
    fl_sweep_collapse *h = build(&m);
    if (!h) return;
    size_t n = 200, early = 0;
    double *q = malloc(3 * n * sizeof *q);
    fl_closest *r = malloc(n * sizeof *r);
    random_queries(&m, q, n);
    fl_error err = {0};
    for (int k = 0; k < 2; k++) {
        double tol = k ? 0.05 : 0.3;
        CHECK_STATUS(fl_sweep_collapse_closest(h, q, n, tol, r, &err), FL_OK, &err);
        for (size_t i = 0; i < n; i++) {
            double bf = (double)brute_distance(&m, q + 3 * i), slack = 1e-12 * (1 + bf);
            CHECK(r[i].lower <= bf + slack && bf <= r[i].upper + slack);
            CHECK(r[i].upper - r[i].lower <= tol);
            early += !r[i].exact;
        }
    }
    CHECK(early > 0);
    free(q);
    free(r);
    fl_sweep_collapse_free(h);
    cm_free(&m);
}

/* Huge coordinates (1e146, with queries up to 1000x farther, near the 1e150 limit) and tiny
 * ones (1e-140, whose squared distances still do not underflow): still exact, and the
 * simplification still collapses (its fold-over test rescales the edges; before, the normals'
 * products overflowed or underflowed and no collapse passed). */
static void test_extreme_scales(void)
{
    double scales[2] = {1e146, 1e-140};
    for (int k = 0; k < 2; k++) {
        fl_mesh m = cm_noisy_torus(16, 8, 0.05);
        for (size_t i = 0; i < 3 * m.vertex_count; i++)
            m.xyz[i] *= scales[k];
        fl_sweep_collapse *h = build(&m);
        if (!h) continue;
        fl_sweep_collapse_info info;
        fl_error err = {0};
        CHECK_STATUS(fl_sweep_collapse_info_get(h, &info, &err), FL_OK, &err);
        CHECK(info.splits > 0);
        double q[3 * 60];
        random_queries(&m, q, 60);
        fl_closest r[60];
        CHECK_STATUS(fl_sweep_collapse_closest(h, q, 60, 0.0, r, &err), FL_OK, &err);
        for (int i = 0; i < 60; i++)
            check_exact(&m, q + 3 * i, r + i);
        fl_sweep_collapse_free(h);
        cm_free(&m);
    }
}

static void test_bad_input(void)
{
    fl_error err = {0};
    fl_sweep_collapse *h = NULL;
    double xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    uint32_t tri[3] = {0, 1, 3};
    fl_mesh m = {3, xyz, 1, tri};
    CHECK_STATUS(fl_sweep_collapse_build(&m, NULL, &h, &err), FL_ERR_INPUT, &err);
    CHECK(h == NULL);
    tri[2] = 2;
    xyz[4] = NAN;
    CHECK_STATUS(fl_sweep_collapse_build(&m, NULL, &h, &err), FL_ERR_INPUT, &err);
    xyz[4] = 0;
    CHECK_STATUS(fl_sweep_collapse_build(NULL, NULL, &h, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_sweep_collapse_build(&m, NULL, &h, &err), FL_OK, &err);
    double q[3] = {INFINITY, 0, 0};
    fl_closest r;
    CHECK_STATUS(fl_sweep_collapse_closest(h, q, 1, 0.0, &r, &err), FL_ERR_USAGE, &err);
    q[0] = 0;
    CHECK_STATUS(fl_sweep_collapse_closest(h, q, 1, -1.0, &r, &err), FL_ERR_USAGE, &err);
    fl_sweep_collapse_free(h);
}

FL_TEST_MAIN(FL_TEST_CASE(test_closed_random), FL_TEST_CASE(test_open_random),
             FL_TEST_CASE(test_messy_random), FL_TEST_CASE(test_soup_random),
             FL_TEST_CASE(test_coherent_walk), FL_TEST_CASE(test_tolerance),
             FL_TEST_CASE(test_extreme_scales), FL_TEST_CASE(test_ball),
             FL_TEST_CASE(test_bad_input))
