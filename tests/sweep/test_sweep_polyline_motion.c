/* Moving polylines (Guéziec §5.3 for the curves of §3): fl_sweep_polyline_update moves the
 * points and inflates the capsules bottom-up. After every update every point lies in the
 * capsule of each node above it, and answers equal brute force over every segment of the
 * moved polyline (sweep_oracle.h), through fresh queries and through a cursor kept across
 * updates; bad input leaves the hierarchy as it was. */
#include <stdint.h>

#include "fl_test.h"
#include "sweep/sweep_internal.h"
#include "sweep_oracle.h"

static unsigned long long seed = 0x5eedf00dULL;

static double rnd(double lo, double hi)
{
    return lo + (hi - lo) * fl_test_rand01(&seed);
}

/* The moving curve: `at` holds n points of `dim` doubles (the library's layout), `flat` the
 * same points lifted to 3D for the oracle. */
typedef struct curve {
    size_t n;
    int dim, closed;
    double *at, *flat;
} curve;

static void lift(curve *cv)
{
    for (size_t i = 0; i < cv->n; i++)
        for (int c = 0; c < 3; c++)
            cv->flat[3 * i + c] = c < cv->dim ? cv->at[(size_t)cv->dim * i + c] : 0;
}

/* A wobbly circle (2D) or helix (3D) of n points; every 11th point repeats the one before. */
static curve curve_make(size_t n, int dim, int closed)
{
    curve cv = {n, dim, closed, calloc(n * (size_t)dim, sizeof(double)),
                calloc(3 * n, sizeof(double))};
    for (size_t i = 0; i < n; i++) {
        double *x = cv.at + (size_t)dim * i, a = 6.283185307179586 * (double)i / (double)n;
        if (i % 11 == 4) {
            for (int c = 0; c < dim; c++)
                x[c] = x[c - dim];
            continue;
        }
        x[0] = (1 + rnd(-0.05, 0.05)) * cos(a);
        x[1] = (1 + rnd(-0.05, 0.05)) * sin(a);
        if (dim == 3) x[2] = closed ? 0.3 * cos(4 * a) : 0.4 * a;
    }
    lift(&cv);
    return cv;
}

static size_t curve_segments(const curve *cv)
{
    return cv->closed ? cv->n : cv->n - 1;
}

/* Moves the points: kind 0 a small smooth wave, 1 a large random jump of every point, 2 all
 * points onto one spot, 3 a rigid turn plus shift, 4 every other point onto its neighbour
 * (duplicates), 5 a stretch along x. */
static void curve_move(curve *cv, int kind, double phase)
{
    double ca = cos(0.7), sa = sin(0.7);
    for (size_t i = 0; i < cv->n; i++) {
        double *x = cv->at + (size_t)cv->dim * i;
        switch (kind) {
        case 0:
            for (int c = 0; c < cv->dim; c++)
                x[c] += 0.02 * sin(5.0 * (double)i / (double)cv->n + phase + c);
            break;
        case 1:
            for (int c = 0; c < cv->dim; c++)
                x[c] += rnd(-1, 1);
            break;
        case 2:
            for (int c = 0; c < cv->dim; c++)
                x[c] = 0.5 - 0.25 * c;
            break;
        case 3: {
            double u = x[0], v = x[1];
            x[0] = ca * u - sa * v + 0.3, x[1] = sa * u + ca * v - 0.1;
            break;
        }
        case 4:
            if (i % 2 && i + 1 < cv->n)
                for (int c = 0; c < cv->dim; c++)
                    x[c] = x[cv->dim + c];
            break;
        default:
            x[0] *= 3;
        }
    }
    lift(cv);
}

/* The volume invariant (§3.1): every point of a node's chain lies within ε of its chord. */
static void check_capsules(const fl_sweep *s, const curve *cv)
{
    size_t *lo = malloc(s->node_count * sizeof *lo), *hi = malloc(s->node_count * sizeof *hi);
    int bad = 0;
    for (size_t i = s->node_count; i-- > 0;) { /* children after parents: bottom-up */
        const fl_sweep_node *node = s->nodes + i;
        if (node->child[0] == FL_SWEEP_LEAF) {
            lo[i] = node->element, hi[i] = node->element + 1;
            continue;
        }
        lo[i] = lo[node->child[0]], hi[i] = hi[node->child[1]];
        for (size_t k = lo[i]; k <= hi[i]; k++) {
            ld d = oracle_segment(cv->flat + 3 * (k % cv->n), node->v, node->v + 3);
            bad += d > node->eps;
        }
    }
    CHECK_MSG(bad == 0, "%d points outside their capsules", bad);
    free(lo);
    free(hi);
}

static void check_answer(const curve *cv, const double *q, const fl_closest *r)
{
    double q3[3] = {q[0], q[1], cv->dim == 3 ? q[2] : 0}, size = 0;
    for (size_t i = 0; i < 3 * cv->n; i++)
        size = fmax(size, fabs(cv->flat[i]));
    ld best = INFINITY;
    for (size_t e = 0; e < curve_segments(cv); e++) {
        ld d = oracle_polyline_element(cv->flat, cv->n, e, q3);
        if (d < best) best = d;
    }
    double tol = 1e-12 * (size + fabs(q3[0]) + fabs(q3[1]) + fabs(q3[2]));
    CHECK(r->exact);
    CHECK_NEAR(r->distance, (double)best, tol);
    CHECK(r->element < curve_segments(cv));
    if (r->element >= curve_segments(cv)) return;
    CHECK_NEAR((double)oracle_polyline_element(cv->flat, cv->n, r->element, q3), (double)best,
               tol);
    const double *a = cv->flat + 3 * r->element, *b = cv->flat + 3 * ((r->element + 1) % cv->n);
    for (int c = 0; c < 3; c++)
        CHECK_NEAR(r->bary[0] * a[c] + r->bary[1] * b[c], r->point[c], tol);
}

/* A query near the curve, far away, or on a segment. */
static void curve_query(const curve *cv, int kind, double *q)
{
    if (kind % 3 == 2) {
        size_t e = fl_test_rand_u64(&seed) % curve_segments(cv);
        double t = rnd(0, 1);
        for (int c = 0; c < cv->dim; c++)
            q[c] = (1 - t) * cv->flat[3 * e + c] + t * cv->flat[3 * ((e + 1) % cv->n) + c];
        return;
    }
    double span = kind % 3 ? 500 : 3;
    for (int c = 0; c < cv->dim; c++)
        q[c] = rnd(-span, span);
}

/* Builds, then moves through `steps` updates of the given kinds; after each, the capsules
 * and nq queries (fresh and through a cursor kept from the start) are checked. */
static void run_motion(curve cv, const int *kinds, int steps, int nq)
{
    fl_error err;
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    CHECK_STATUS(fl_sweep_polyline_build(cv.at, cv.n, cv.dim, cv.closed, NULL, &s, &err), FL_OK,
                 &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    for (int step = 0; s && cur && step < steps; step++) {
        curve_move(&cv, kinds[step], 0.3 * step);
        CHECK_STATUS(fl_sweep_polyline_update(s, cv.at, &err), FL_OK, &err);
        check_capsules(s, &cv);
        for (int i = 0; i < nq; i++) {
            double q[3];
            fl_closest r;
            curve_query(&cv, i, q);
            CHECK_STATUS(fl_sweep_closest(s, q, 1, 0, &r, &err), FL_OK, &err);
            check_answer(&cv, q, &r);
            CHECK_STATUS(fl_sweep_cursor_closest(cur, q, 0, &r, &err), FL_OK, &err);
            check_answer(&cv, q, &r);
        }
    }
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
    free(cv.at);
    free(cv.flat);
}

static void test_polyline_motion_smooth_and_large_exact(void)
{
    int kinds[12] = {0, 0, 0, 1, 0, 3, 0, 5, 0, 1, 0, 0};
    run_motion(curve_make(400, 2, 1), kinds, 12, 30);
    run_motion(curve_make(400, 2, 0), kinds, 12, 30);
    run_motion(curve_make(600, 3, 0), kinds, 12, 30);
    run_motion(curve_make(300, 3, 1), kinds, 12, 30);
}

static void test_polyline_motion_degenerate_exact(void)
{
    int kinds[6] = {4, 0, 2, 1, 0, 4};
    run_motion(curve_make(257, 3, 1), kinds, 6, 30);
    run_motion(curve_make(130, 2, 0), kinds, 6, 30);
    int two[4] = {1, 2, 1, 3};
    run_motion(curve_make(2, 2, 0), two, 4, 20); /* one segment */
    run_motion(curve_make(2, 3, 1), two, 4, 20); /* two segments, back and forth */
    run_motion(curve_make(3, 3, 1), two, 4, 20);
}

/* A slow coherent walk through one cursor while the curve waves a little every step (§5.1,
 * §5.2): exact at every step, and the kept queue pays (fewer distances than from the root). */
static void test_polyline_motion_cursor_walk_exact(void)
{
    curve cv = curve_make(2000, 3, 1);
    fl_error err;
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    CHECK_STATUS(fl_sweep_polyline_build(cv.at, cv.n, 3, 1, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    size_t walked = 0, fresh = 0;
    for (int step = 0; s && cur && step < 200; step++) {
        curve_move(&cv, 0, 0.01 * step);
        CHECK_STATUS(fl_sweep_polyline_update(s, cv.at, &err), FL_OK, &err);
        double a = 0.01 * step, q[3] = {1.2 * cos(a), 1.2 * sin(a), 0.1};
        fl_closest r, rf;
        CHECK_STATUS(fl_sweep_cursor_closest(cur, q, 0, &r, &err), FL_OK, &err);
        check_answer(&cv, q, &r);
        CHECK_STATUS(fl_sweep_closest(s, q, 1, 0, &rf, &err), FL_OK, &err);
        walked += r.visited, fresh += rf.visited;
    }
    printf("polyline walk over 200 updates: %zu distances through the cursor, %zu from the root\n",
           walked, fresh);
    CHECK(walked < fresh);
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
    free(cv.at);
    free(cv.flat);
}

static void test_polyline_motion_rejects_bad_input(void)
{
    curve cv = curve_make(50, 2, 0);
    fl_error err;
    fl_sweep *s = NULL;
    CHECK_STATUS(fl_sweep_polyline_build(cv.at, cv.n, 2, 0, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_polyline_update(NULL, cv.at, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_sweep_polyline_update(s, NULL, &err), FL_ERR_USAGE, &err);
    /* fl_sweep_update_vertices is for meshes, fl_sweep_polyline_update for polylines */
    CHECK_STATUS(fl_sweep_update_vertices(s, cv.flat, &err), FL_ERR_USAGE, &err);
    double poison[4] = {NAN, INFINITY, -1e151, -INFINITY};
    double *moved = malloc(2 * cv.n * sizeof *moved);
    for (int i = 0; i < 4; i++) {
        for (size_t k = 0; k < 2 * cv.n; k++)
            moved[k] = cv.at[k] + 5;
        moved[17 + i] = poison[i];
        CHECK_STATUS(fl_sweep_polyline_update(s, moved, &err), FL_ERR_INPUT, &err);
    }
    /* unchanged: still exact for the original points */
    check_capsules(s, &cv);
    for (int i = 0; i < 20; i++) {
        double q[2];
        fl_closest r;
        curve_query(&cv, i, q);
        CHECK_STATUS(fl_sweep_closest(s, q, 1, 0, &r, &err), FL_OK, &err);
        check_answer(&cv, q, &r);
    }
    fl_mesh m = {3, (double[]){0, 0, 0, 1, 0, 0, 0, 1, 0}, 1, (uint32_t[]){0, 1, 2}};
    fl_sweep *ms = NULL;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &ms, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_polyline_update(ms, m.xyz, &err), FL_ERR_USAGE, &err);
    fl_sweep_free(ms);
    free(moved);
    fl_sweep_free(s);
    free(cv.at);
    free(cv.flat);
}

FL_TEST_MAIN(FL_TEST_CASE(test_polyline_motion_smooth_and_large_exact),
             FL_TEST_CASE(test_polyline_motion_degenerate_exact),
             FL_TEST_CASE(test_polyline_motion_cursor_walk_exact),
             FL_TEST_CASE(test_polyline_motion_rejects_bad_input))
