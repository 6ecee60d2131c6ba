/* Polyline closest-point queries (§3) against brute force over every segment. */
#include <stdint.h>

#include "fl_test.h"
#include "sweep/sweep_internal.h"
#include "sweep_oracle.h"

static unsigned long long rng = 0x9011ULL;

static double urand(double lo, double hi)
{
    return lo + (hi - lo) * fl_test_rand01(&rng);
}

/* A polyline in the caller's layout (dim doubles a point) and its 3D copy for the oracle. */
typedef struct polyline {
    size_t n;
    int dim, closed;
    double *pts, *xyz;
} polyline;

static polyline polyline_new(size_t n, int dim, int closed)
{
    polyline p = {n, dim, closed, malloc(n * (size_t)dim * sizeof(double)),
                  calloc(3 * n, sizeof(double))};
    return p;
}

static void polyline_sync(polyline *p)
{
    for (size_t i = 0; i < p->n; i++)
        for (int c = 0; c < p->dim; c++)
            p->xyz[3 * i + c] = p->pts[(size_t)p->dim * i + c];
}

static void polyline_free(polyline *p)
{
    free(p->pts);
    free(p->xyz);
}

/* A noisy circle (2D) or helix (3D); every 17th point is repeated. */
static polyline make_curve(size_t n, int dim, int closed)
{
    polyline p = polyline_new(n, dim, closed);
    for (size_t i = 0; i < n; i++) {
        double *x = p.pts + (size_t)dim * i;
        if (i % 17 == 5) {
            memcpy(x, x - dim, (size_t)dim * sizeof *x);
            continue;
        }
        double t = 6.283185307179586 * (double)i / (double)n, r = 1 + urand(-0.05, 0.05);
        x[0] = r * cos(t);
        x[1] = r * sin(t);
        if (dim == 3) x[2] = closed ? 0.2 * sin(3 * t) : 0.3 * t;
    }
    polyline_sync(&p);
    return p;
}

/* A random walk: a wiggly, self-crossing open curve. */
static polyline make_walk(size_t n, int dim)
{
    polyline p = polyline_new(n, dim, 0);
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < dim; c++)
            p.pts[(size_t)dim * i + c] =
                (i ? p.pts[(size_t)dim * (i - 1) + c] : 0) + urand(-0.1, 0.1);
    polyline_sync(&p);
    return p;
}

static size_t segments(const polyline *p)
{
    return p->closed ? p->n : p->n - 1;
}

static ld brute_distance(const polyline *p, const double *q3)
{
    ld best = INFINITY;
    for (size_t i = 0; i < segments(p); i++) {
        ld d = oracle_polyline_element(p->xyz, p->n, i, q3);
        if (d < best) best = d;
    }
    return best;
}

static void check_exact(const polyline *p, const double *q, const fl_closest *r)
{
    double q3[3] = {q[0], q[1], p->dim == 3 ? q[2] : 0};
    double tol = 1e-12 * (10 + fabs(q3[0]) + fabs(q3[1]) + fabs(q3[2]));
    ld bf = brute_distance(p, q3);
    CHECK(r->exact);
    CHECK_NEAR(r->distance, (double)bf, tol);
    CHECK(r->element < segments(p));
    if (r->element >= segments(p)) return;
    CHECK_NEAR((double)oracle_polyline_element(p->xyz, p->n, r->element, q3), (double)bf, tol);
    const double *a = p->xyz + 3 * r->element, *b = p->xyz + 3 * ((r->element + 1) % p->n);
    for (int c = 0; c < 3; c++)
        CHECK_NEAR(r->bary[0] * a[c] + r->bary[1] * b[c], r->point[c], tol);
    CHECK(r->bary[0] >= 0 && r->bary[1] >= 0 && r->bary[2] == 0);
}

static double *make_queries(const polyline *p, size_t nq)
{
    double *q = malloc(nq * (size_t)p->dim * sizeof *q);
    for (size_t i = 0; i < nq; i++) {
        double *x = q + (size_t)p->dim * i;
        if (i % 3 == 2) { /* on the curve */
            size_t s = fl_test_rand_u64(&rng) % segments(p);
            double t = urand(0, 1);
            for (int c = 0; c < p->dim; c++)
                x[c] = (1 - t) * p->xyz[3 * s + c] + t * p->xyz[3 * ((s + 1) % p->n) + c];
        } else {
            double span = i % 3 ? 1000 : 2;
            for (int c = 0; c < p->dim; c++)
                x[c] = urand(-span, span);
        }
    }
    return q;
}

static void check_polyline_queries(polyline *p, size_t nq)
{
    fl_error err;
    fl_sweep *s = NULL;
    CHECK_STATUS(fl_sweep_polyline_build(p->pts, p->n, p->dim, p->closed, NULL, &s, &err), FL_OK,
                 &err);
    if (!s) return;
    CHECK_EQ_INT(fl_sweep_element_count(s), segments(p));
    CHECK_EQ_INT(fl_sweep_dim(s), p->dim);
    double *q = make_queries(p, nq);
    fl_closest *r = calloc(nq, sizeof *r);
    CHECK_STATUS(fl_sweep_closest(s, q, nq, 0, r, &err), FL_OK, &err);
    for (size_t i = 0; i < nq; i++)
        check_exact(p, q + (size_t)p->dim * i, r + i);
    free(q);
    free(r);
    fl_sweep_free(s);
}

static void test_sweep_polylines_2d_3d_open_closed_match_brute_force(void)
{
    for (int dim = 2; dim <= 3; dim++)
        for (int closed = 0; closed <= 1; closed++) {
            polyline p = make_curve(500, dim, closed);
            check_polyline_queries(&p, 300);
            polyline_free(&p);
        }
    polyline w = make_walk(800, 2);
    check_polyline_queries(&w, 300);
    polyline_free(&w);
    w = make_walk(800, 3);
    check_polyline_queries(&w, 300);
    polyline_free(&w);
    polyline two = make_walk(2, 3);
    check_polyline_queries(&two, 30);
    two.closed = 1;
    check_polyline_queries(&two, 30);
    polyline_free(&two);
}

/* §3.1: every vertex of a chain lies within ε of its node's segment, and (end-point fit) the
 * node's segment joins two vertices of the curve. */
static void test_sweep_end_point_fit_bounds_its_chain(void)
{
    polyline p = make_walk(300, 3);
    fl_sweep *s = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_polyline_build(p.pts, p.n, 3, 0, NULL, &s, &err), FL_OK, &err);
    if (!s) return;
    uint32_t *stack = malloc(s->node_count * sizeof *stack);
    for (size_t i = 0; i < s->node_count; i++) {
        const fl_sweep_node *node = s->nodes + i;
        size_t top = 0;
        stack[top++] = (uint32_t)i;
        while (top > 0) {
            const fl_sweep_node *d = s->nodes + stack[--top];
            if (d->child[0] != FL_SWEEP_LEAF) {
                stack[top++] = d->child[0];
                stack[top++] = d->child[1];
                continue;
            }
            for (int k = 0; k < 2; k++) {
                const double *x = p.xyz + 3 * (d->element + (size_t)k);
                ld e = oracle_segment(x, node->v, node->v + 3);
                CHECK_MSG(e <= node->eps, "node %zu eps %g < %Lg", i, node->eps, e);
            }
        }
    }
    free(stack);
    fl_sweep_free(s);
    polyline_free(&p);
}

/* §3.2 early stop: the interval brackets the true distance and is narrower than asked. */
static void test_sweep_polyline_tolerance_interval_brackets_distance(void)
{
    polyline p = make_walk(1000, 2);
    fl_sweep *s = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_polyline_build(p.pts, p.n, 2, 0, NULL, &s, &err), FL_OK, &err);
    double *q = make_queries(&p, 300);
    int inexact = 0;
    const double tols[2] = {1e-2, 0.5};
    for (int k = 0; k < 2 && s; k++)
        for (size_t i = 0; i < 300; i++) {
            fl_closest r;
            CHECK_STATUS(fl_sweep_closest(s, q + 2 * i, 1, tols[k], &r, &err), FL_OK, &err);
            double q3[3] = {q[2 * i], q[2 * i + 1], 0}, bf = (double)brute_distance(&p, q3);
            double slack = 1e-12 * (10 + fabs(q3[0]) + fabs(q3[1]));
            CHECK(r.lower <= bf + slack && bf <= r.upper + slack);
            CHECK(r.upper - r.lower <= tols[k]);
            inexact += !r.exact;
        }
    CHECK(inexact > 0);
    free(q);
    fl_sweep_free(s);
    polyline_free(&p);
}

/* §3.3: along a slow random walk inside a coarse polygon the coherence ball answers many
 * queries in constant time (one distance), and every answer stays exact. (The ball's radius
 * is half the gap to the second interval, so it shrinks with the segment length.) */
static void test_sweep_polyline_coherent_walk_reuses_ball(void)
{
    polyline p = make_curve(12, 2, 1);
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_polyline_build(p.pts, p.n, 2, 1, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    double q[2] = {0.3, 0.2};
    int reused = 0;
    for (int step = 0; step < 500 && cur; step++) {
        q[0] += urand(-0.001, 0.001);
        q[1] += urand(-0.001, 0.001);
        fl_closest r;
        CHECK_STATUS(fl_sweep_cursor_closest(cur, q, 0, &r, &err), FL_OK, &err);
        check_exact(&p, q, &r);
        if (r.reused) CHECK_EQ_INT(r.visited, 1);
        reused += r.reused;
    }
    CHECK_MSG(reused > 100, "only %d of 500 steps reused the ball", reused);
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
    polyline_free(&p);
}

static void test_sweep_polyline_knearest_matches_brute_force(void)
{
    polyline p = make_walk(300, 3);
    fl_sweep *s = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_polyline_build(p.pts, p.n, 3, 0, NULL, &s, &err), FL_OK, &err);
    uint32_t el[10];
    double d[10];
    for (int i = 0; i < 30 && s; i++) {
        double q[3] = {urand(-1, 1), urand(-1, 1), urand(-1, 1)};
        size_t found = 0;
        CHECK_STATUS(fl_sweep_knearest(s, q, 10, el, d, &found, &err), FL_OK, &err);
        CHECK_EQ_INT(found, 10);
        ld prev = 0;
        size_t below = 0;
        for (size_t j = 0; j < found; j++) {
            ld e = oracle_polyline_element(p.xyz, p.n, el[j], q);
            CHECK_NEAR(d[j], (double)e, 1e-12);
            CHECK(e >= prev - 1e-12);
            prev = e;
        }
        for (size_t j = 0; j + 1 < p.n; j++)
            below += oracle_polyline_element(p.xyz, p.n, j, q) < prev - 1e-12;
        CHECK(below <= 9);
    }
    fl_sweep_free(s);
    polyline_free(&p);
}

/* All points equal: every segment is a point, every ε is 0, and the distance is |q - p|. */
static void test_sweep_polyline_of_one_repeated_point(void)
{
    double pts[10] = {1, 2, 1, 2, 1, 2, 1, 2, 1, 2}, q[2] = {4, 6};
    fl_sweep *s = NULL;
    fl_error err;
    for (int closed = 0; closed <= 1; closed++) {
        CHECK_STATUS(fl_sweep_polyline_build(pts, 5, 2, closed, NULL, &s, &err), FL_OK, &err);
        fl_closest r;
        CHECK_STATUS(fl_sweep_closest(s, q, 1, 0, &r, &err), FL_OK, &err);
        CHECK(r.exact);
        CHECK_NEAR(r.distance, 5, 1e-15);
        CHECK_NEAR(r.point[0], 1, 0);
        CHECK_NEAR(r.point[1], 2, 0);
        fl_sweep_free(s);
    }
}

static int cancel_at_first_report(void *user, const char *stage, double fraction)
{
    (void)stage;
    (void)fraction;
    ++*(int *)user;
    return 1;
}

/* A progress callback that asks to stop ends the build with "cancelled" and no hierarchy. */
static void test_sweep_build_can_be_cancelled(void)
{
    polyline p = make_curve(70000, 2, 1);
    int calls = 0;
    fl_sweep_options opt = {.progress = cancel_at_first_report, .progress_user = &calls};
    fl_sweep *s = NULL;
    fl_error err;
    CHECK_STATUS(fl_sweep_polyline_build(p.pts, p.n, 2, 1, &opt, &s, &err), FL_ERR_ALGORITHM, &err);
    CHECK(s == NULL);
    CHECK_EQ_INT(calls, 1);
    polyline_free(&p);
}

static void test_sweep_polyline_rejects_bad_input(void)
{
    fl_error err;
    fl_sweep *s = NULL;
    double pts[6] = {0, 0, 1, 0, 1, NAN};
    CHECK_STATUS(fl_sweep_polyline_build(pts, 3, 2, 0, NULL, &s, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_sweep_polyline_build(pts, 1, 2, 0, NULL, &s, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_sweep_polyline_build(pts, 2, 4, 0, NULL, &s, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_sweep_polyline_build(NULL, 2, 2, 0, NULL, &s, &err), FL_ERR_USAGE, &err);
    CHECK(s == NULL);
}

FL_TEST_MAIN(FL_TEST_CASE(test_sweep_polylines_2d_3d_open_closed_match_brute_force),
             FL_TEST_CASE(test_sweep_end_point_fit_bounds_its_chain),
             FL_TEST_CASE(test_sweep_polyline_tolerance_interval_brackets_distance),
             FL_TEST_CASE(test_sweep_polyline_coherent_walk_reuses_ball),
             FL_TEST_CASE(test_sweep_polyline_knearest_matches_brute_force),
             FL_TEST_CASE(test_sweep_polyline_of_one_repeated_point),
             FL_TEST_CASE(test_sweep_build_can_be_cancelled),
             FL_TEST_CASE(test_sweep_polyline_rejects_bad_input))
