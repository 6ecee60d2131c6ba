/* The walk region of coherent cursor streams (src/sweep/walk.c, issue #9): every answer given
 * inside a certified region is checked query by query against the brute force over all
 * elements (long-double oracle sharing no code with src/sweep), on walks that cross the medial
 * axis, run along it (exact ties between faces), pass the centre of a cube (all faces tied),
 * stay far from a fine grid (more near-equidistant triangles than a region holds), follow a
 * shape update, and interleave jumps and tolerance queries. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"
#include "sweep/sweep_internal.h"
#include "test_collapse_meshes.h"

static unsigned long long rng = 0x3a1cULL;

static double urand(double lo, double hi)
{
    return lo + (hi - lo) * fl_test_rand01(&rng);
}

/* Walk statistics of one stream. */
typedef struct walk_count {
    size_t queries, answered, built, trimmed, visited;
} walk_count;

/* One query through the cursor, checked against brute force; counts its cost. */
static void walk_query(const fl_mesh *m, fl_sweep_cursor *cur, const double *q, walk_count *wc)
{
    fl_closest r;
    fl_error err;
    CHECK_STATUS(fl_sweep_cursor_closest(cur, q, 0, &r, &err), FL_OK, &err);
    check_exact(m, q, &r);
    if (r.reused) CHECK_EQ_INT((int)r.visited, 1);
    wc->queries++;
    wc->visited += r.visited;
}

static void walk_stats(fl_sweep_cursor *cur, walk_count *wc)
{
    fl_sweep_cursor_walk_stats(cur, &wc->answered, &wc->built, &wc->trimmed);
}

/* A noisy torus: slow random walks from several starts (inside the tube, in the hole, outside)
 * stay exact; most steps are answered inside a region and the stream computes under a third
 * of the distances of the same queries each from the root. */
static void test_walk_torus_is_exact_and_cheaper_than_independent_queries(void)
{
    fl_mesh m = cm_noisy_torus(40, 20, 0.05);
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    const double starts[4][3] = {{1.0, 0.0, 0.05}, {0.1, 0.2, 0.0}, {1.6, 0.3, 0.4}, {0, 1, 0.3}};
    walk_count wc = {0};
    size_t fresh = 0;
    for (int k = 0; k < 4 && cur; k++) {
        double q[3];
        memcpy(q, starts[k], sizeof q);
        for (int step = 0; step < 250; step++) {
            for (int c = 0; c < 3; c++)
                q[c] += urand(-0.002, 0.002);
            walk_query(&m, cur, q, &wc);
            fl_closest r;
            CHECK_STATUS(fl_sweep_closest(s, q, 1, 0, &r, &err), FL_OK, &err);
            fresh += r.visited;
        }
    }
    walk_stats(cur, &wc);
    CHECK_MSG(wc.answered > wc.queries / 2, "%zu of %zu answered in a region", wc.answered,
              wc.queries);
    CHECK_MSG(3 * wc.visited < fresh, "walk %zu vs independent %zu distances", wc.visited, fresh);
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
    cm_free(&m);
}

/* The surface of the cube [-1,1]^3, every face an n x n grid of squares split in two. */
static fl_mesh cube_mesh(int n)
{
    fl_mesh m = cm_alloc(6 * (size_t)(n + 1) * (n + 1), 12 * (size_t)n * n);
    size_t v = 0, t = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int side = -1; side <= 1; side += 2) {
            size_t base = v;
            for (int i = 0; i <= n; i++)
                for (int j = 0; j <= n; j++) {
                    double *p = m.xyz + 3 * v++;
                    p[axis] = side;
                    p[(axis + 1) % 3] = -1 + 2.0 * i / n;
                    p[(axis + 2) % 3] = -1 + 2.0 * j / n;
                }
            for (int i = 0; i < n; i++)
                for (int j = 0; j < n; j++) {
                    uint32_t a = (uint32_t)(base + (size_t)i * (n + 1) + j), b = a + 1;
                    uint32_t c = a + (uint32_t)(n + 1), d = c + 1;
                    uint32_t q[6] = {a, c, d, a, d, b};
                    memcpy(m.tri + 3 * t, q, sizeof q);
                    t += 2;
                }
        }
    return m;
}

/* Near-ties and the medial axis: inside the cube the closest face changes across the planes
 * x = ±y etc.; walks crossing them, a walk exactly on x = y (two faces tied at every step),
 * one through the centre (all six tied), and one outside around an edge and a corner (where
 * the closest feature switches between faces, the edge and the corner). */
static void test_walk_cube_crossing_and_along_the_medial_axis(void)
{
    fl_mesh m = cube_mesh(4);
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    walk_count wc = {0};
    double q[3];
    for (int i = 0; i <= 400 && cur; i++) { /* crossing x = y and x = -y, with a wobble */
        double a = -0.6 + 1.2 * i / 400;
        q[0] = a, q[1] = 0.3 * sin(9 * a) + urand(-1e-3, 1e-3), q[2] = 0.1;
        walk_query(&m, cur, q, &wc);
    }
    for (int i = 0; i <= 300 && cur; i++) { /* exactly on x = y: faces x = 1 and y = 1 tie */
        double a = 0.2 + 0.5 * i / 300;
        q[0] = q[1] = a, q[2] = 0.05 * sin(7 * a);
        walk_query(&m, cur, q, &wc);
    }
    for (int i = 0; i <= 300 && cur; i++) { /* through the centre, all faces tied there */
        double a = -0.3 + 0.6 * i / 300;
        q[0] = a, q[1] = 0.5 * a, q[2] = -0.25 * a;
        walk_query(&m, cur, q, &wc);
    }
    for (int i = 0; i <= 400 && cur; i++) { /* outside: around the edge x = y = 1, the corner */
        double a = 0.0 + 1.6 * i / 400;
        q[0] = 1 + 0.2 * cos(a), q[1] = 1 + 0.2 * sin(a), q[2] = 0.6 + 0.6 * a;
        walk_query(&m, cur, q, &wc);
    }
    walk_stats(cur, &wc);
    CHECK_MSG(wc.answered > wc.queries / 4, "%zu of %zu answered in a region", wc.answered,
              wc.queries);
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
    cm_free(&m);
}

/* Far above a fine grid many triangles are nearly equidistant, more than a region holds: the
 * region keeps the nearest and its bound drops to the farthest it let go; answers stay exact. */
static void test_walk_far_from_a_fine_grid_overflows_the_region(void)
{
    fl_mesh m = cm_open_grid(24, 0.02);
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < m.vertex_count; i++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], m.xyz[3 * i + c]);
            hi[c] = fmax(hi[c], m.xyz[3 * i + c]);
        }
    double q[3] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), hi[2] + 3 * (hi[0] - lo[0])};
    double step = 0.02 * (hi[0] - lo[0]);
    walk_count wc = {0};
    for (int i = 0; i < 300 && cur; i++) {
        for (int c = 0; c < 3; c++)
            q[c] += urand(-step, step);
        walk_query(&m, cur, q, &wc);
    }
    walk_stats(cur, &wc);
    CHECK_MSG(wc.built > 0 && wc.trimmed > 0, "%zu regions, %zu members let go", wc.built,
              wc.trimmed);
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
    cm_free(&m);
}

/* A shape update (§5.2) invalidates the region: the walk goes on exact on the moved mesh. */
static void test_walk_follows_a_vertex_update(void)
{
    fl_mesh m = cm_noisy_torus(30, 15, 0.03);
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    double q[3] = {1.2, 0.1, 0.2};
    walk_count wc = {0};
    for (int frame = 0; frame < 4 && cur; frame++) {
        for (int step = 0; step < 80; step++) {
            for (int c = 0; c < 3; c++)
                q[c] += urand(-0.002, 0.002);
            walk_query(&m, cur, q, &wc);
        }
        for (size_t i = 0; i < m.vertex_count; i++) /* a small swelling */
            for (int c = 0; c < 3; c++)
                m.xyz[3 * i + c] *= 1 + 0.002 * (c + 1);
        CHECK_STATUS(fl_sweep_update_vertices(s, m.xyz, &err), FL_OK, &err);
    }
    walk_stats(cur, &wc);
    CHECK(wc.answered > 0 && wc.built >= 4);
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
    cm_free(&m);
}

/* Walks interleaved with jumps (the queue from the root) and tolerance queries (the kept
 * queue's early stop): exact answers stay exact, intervals bracket the distance. */
static void test_walk_mixed_with_jumps_and_tolerances(void)
{
    fl_mesh m = cm_noisy_torus(40, 20, 0.05);
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    double q[3] = {1.3, 0.2, 0.4};
    walk_count wc = {0};
    for (int step = 0; step < 600 && cur; step++) {
        if (step % 50 == 49)
            for (int c = 0; c < 3; c++)
                q[c] = urand(-1.5, 1.5);
        for (int c = 0; c < 3; c++)
            q[c] += urand(-0.003, 0.003);
        if (step % 7 != 3) {
            walk_query(&m, cur, q, &wc);
            continue;
        }
        fl_closest r;
        CHECK_STATUS(fl_sweep_cursor_closest(cur, q, 0.01, &r, &err), FL_OK, &err);
        double bf = (double)brute_distance(&m, q);
        CHECK(r.lower <= bf + 1e-12 && bf <= r.upper + 1e-12 && r.upper - r.lower <= 0.01);
    }
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
    cm_free(&m);
}

/* Distance from p (2D) to the closed polyline pts[0..n), every segment tried (long double). */
static ld polyline_brute(const double *pts, size_t n, const double *p)
{
    ld best = INFINITY;
    for (size_t i = 0; i < n; i++) {
        double a[3] = {pts[2 * i], pts[2 * i + 1], 0};
        double b[3] = {pts[2 * ((i + 1) % n)], pts[2 * ((i + 1) % n) + 1], 0};
        double q[3] = {p[0], p[1], 0};
        ld d = oracle_segment(q, a, b);
        if (d < best) best = d;
    }
    return best;
}

/* A closed 2D polyline (a thin rectangle, sides split into many segments): walks across its
 * midline (the medial axis, where the two long sides tie) and exactly along it. */
static void test_walk_polyline_across_and_along_the_midline(void)
{
    enum { SIDE = 40 };
    double pts[4 * SIDE * 2];
    size_t n = 0;
    for (int i = 0; i < SIDE; i++, n++)
        pts[2 * n] = -2 + 4.0 * i / SIDE, pts[2 * n + 1] = -0.5;
    for (int i = 0; i < SIDE; i++, n++)
        pts[2 * n] = 2, pts[2 * n + 1] = -0.5 + 1.0 * i / SIDE;
    for (int i = 0; i < SIDE; i++, n++)
        pts[2 * n] = 2 - 4.0 * i / SIDE, pts[2 * n + 1] = 0.5;
    for (int i = 0; i < SIDE; i++, n++)
        pts[2 * n] = -2, pts[2 * n + 1] = 0.5 - 1.0 * i / SIDE;
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_polyline_build(pts, n, 2, 1, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    size_t count = 0;
    for (int i = 0; i < 1200 && cur; i++) {
        double a = -1.8 + 3.6 * i / 1200, q[2];
        q[0] = a;
        q[1] = i < 600 ? 0.3 * sin(40 * a) : 0; /* zigzag across, then on the midline */
        fl_closest r;
        CHECK_STATUS(fl_sweep_cursor_closest(cur, q, 0, &r, &err), FL_OK, &err);
        double bf = (double)polyline_brute(pts, n, q);
        CHECK(r.exact);
        CHECK_NEAR(r.distance, bf, 1e-12);
        CHECK(r.element < n);
        if (r.element < n) {
            size_t e = r.element;
            double a3[3] = {pts[2 * e], pts[2 * e + 1], 0}, q3[3] = {q[0], q[1], 0};
            double b3[3] = {pts[2 * ((e + 1) % n)], pts[2 * ((e + 1) % n) + 1], 0};
            CHECK_NEAR((double)oracle_segment(q3, a3, b3), bf, 1e-12);
        }
        count++;
    }
    size_t answered, built, trimmed;
    fl_sweep_cursor_walk_stats(cur, &answered, &built, &trimmed);
    CHECK_MSG(answered > count / 2, "%zu of %zu answered in a region", answered, count);
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
}

FL_TEST_MAIN(FL_TEST_CASE(test_walk_torus_is_exact_and_cheaper_than_independent_queries),
             FL_TEST_CASE(test_walk_cube_crossing_and_along_the_medial_axis),
             FL_TEST_CASE(test_walk_far_from_a_fine_grid_overflows_the_region),
             FL_TEST_CASE(test_walk_follows_a_vertex_update),
             FL_TEST_CASE(test_walk_mixed_with_jumps_and_tolerances),
             FL_TEST_CASE(test_walk_polyline_across_and_along_the_midline))
