/* Moving shapes (Guéziec §5.2, §5.3): queries against a mesh in rigid motion and against a
 * deforming mesh whose hierarchy is updated in place, compared with brute force over every
 * triangle of the moved mesh (sweep_oracle.h) and with a hierarchy built afresh. */
#include <stdint.h>

#include "fl_test.h"
#include "sweep/sweep_internal.h"
#include "mesh_answer_check.h"
#include "sweep_volume_check.h"
#include "sweep_work.h"

static unsigned long long rng = 0xd1a9ULL;

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

/* An open 6x6 grid with a degenerate (collinear) triangle, a repeated-vertex triangle, a
 * duplicated vertex and a repeated triangle appended. */
static fl_mesh make_messy(void)
{
    const int g = 6;
    size_t nv = (size_t)g * g + 3, nt = 2 * (size_t)(g - 1) * (g - 1) + 3;
    fl_mesh m = mesh_alloc(nv, nt);
    for (int i = 0; i < g; i++)
        for (int j = 0; j < g; j++) {
            double *p = m.xyz + 3 * ((size_t)i * g + j);
            p[0] = i, p[1] = j, p[2] = 0.2 * sin(i + j);
        }
    size_t t = 0;
    for (int i = 0; i + 1 < g; i++)
        for (int j = 0; j + 1 < g; j++) {
            uint32_t a = (uint32_t)(i * g + j), b = a + (uint32_t)g, c = b + 1, d = a + 1;
            uint32_t *tt = m.tri + 3 * t;
            tt[0] = a, tt[1] = b, tt[2] = c, tt[3] = a, tt[4] = c, tt[5] = d;
            t += 2;
        }
    uint32_t b0 = (uint32_t)(g * g);
    double extra[3][3] = {{8, 0, 0}, {9, 0, 0}, {0, 0, 0}}; /* b0+2 duplicates vertex 0 */
    memcpy(m.xyz + 3 * b0, extra, sizeof extra);
    uint32_t more[3][3] = {{b0, b0 + 1, 0}, {b0, b0, b0 + 1}, {b0 + 2, 1, (uint32_t)g}};
    memcpy(m.tri + 3 * t, more, sizeof more);
    (void)nt;
    return m;
}

/* A query near the mesh (box around it), far from it, or on one of its triangles. */
static void random_query(const fl_mesh *m, int kind, double *p)
{
    double s = mesh_scale(m);
    if (kind % 3 == 0) {
        for (int c = 0; c < 3; c++)
            p[c] = urand(-1.2 * s, 1.2 * s);
    } else if (kind % 3 == 1) {
        for (int c = 0; c < 3; c++)
            p[c] = urand(-100 * s, 100 * s);
    } else {
        size_t t = fl_test_rand_u64(&rng) % m->triangle_count;
        double u = urand(0, 1), v = urand(0, 1 - u);
        for (int c = 0; c < 3; c++)
            p[c] = (1 - u - v) * oracle_vertex(m->xyz, m->tri, t, 0)[c] +
                   u * oracle_vertex(m->xyz, m->tri, t, 1)[c] +
                   v * oracle_vertex(m->xyz, m->tri, t, 2)[c];
    }
}

/* A smooth deformation of the rest shape: a travelling sine wave along x plus a twist about z,
 * and a little noise per vertex (so the motion is not locally rigid either). */
static void deform(const double *rest, double *xyz, size_t nv, double t, double noise)
{
    for (size_t v = 0; v < nv; v++) {
        const double *p = rest + 3 * v;
        double a = 0.4 * t * p[2], ca = cos(a), sa = sin(a);
        xyz[3 * v] = ca * p[0] - sa * p[1] + urand(-noise, noise);
        xyz[3 * v + 1] = sa * p[0] + ca * p[1] + urand(-noise, noise);
        xyz[3 * v + 2] = p[2] + 0.25 * sin(3 * p[0] + t) + urand(-noise, noise);
    }
}

static size_t total_cost(const fl_sweep *s, const double *q, size_t nq)
{
    fl_closest *r = calloc(nq, sizeof *r);
    fl_error err;
    size_t cost = 0;
    for (size_t i = 0; i < nq; i++) {
        CHECK_STATUS(fl_sweep_closest(s, q + 3 * i, 1, 0, r + i, &err), FL_OK, &err);
        cost += r[i].visited;
    }
    free(r);
    return cost;
}

/* §5.3: after each of many deformations (updated in place, never rebuilt) every volume still
 * contains its vertices and the answers equal brute force on the deformed mesh and a hierarchy
 * built afresh from it; a cursor kept across the updates (§5.2 widening) stays exact too. */
static void check_deforming(fl_mesh *m, int frames, double noise, double dt)
{
    fl_error err;
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    CHECK_STATUS(fl_sweep_build(m, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    if (!cur) return;
    double *rest = malloc(3 * m->vertex_count * sizeof *rest);
    memcpy(rest, m->xyz, 3 * m->vertex_count * sizeof *rest);
    double walker[3];
    random_query(m, 0, walker);
    size_t updated_cost = 0, fresh_cost = 0;
    for (int f = 1; f <= frames; f++) {
        deform(rest, m->xyz, m->vertex_count, f * dt, noise);
        CHECK_STATUS(fl_sweep_update_vertices(s, m->xyz, &err), FL_OK, &err);
        check_volumes(s, m);
        fl_sweep *fresh = NULL;
        CHECK_STATUS(fl_sweep_build(m, NULL, &fresh, &err), FL_OK, &err);
        double q[3 * 60];
        for (int i = 0; i < 60; i++)
            random_query(m, i, q + 3 * i);
        fl_closest r[60], rf[60];
        CHECK_STATUS(fl_sweep_closest(s, q, 60, 0, r, &err), FL_OK, &err);
        CHECK_STATUS(fl_sweep_closest(fresh, q, 60, 0, rf, &err), FL_OK, &err);
        for (int i = 0; i < 60; i++) {
            check_exact(m, q + 3 * i, r + i);
            CHECK_NEAR(r[i].distance, rf[i].distance, 1e-13 * (1 + fabs(q[3 * i])));
        }
        updated_cost += total_cost(s, q, 60);
        fresh_cost += total_cost(fresh, q, 60);
        for (int step = 0; step < 5; step++) { /* the kept queue across the update */
            for (int c = 0; c < 3; c++)
                walker[c] += urand(-0.01, 0.01);
            fl_closest w;
            CHECK_STATUS(fl_sweep_cursor_closest(cur, walker, 0, &w, &err), FL_OK, &err);
            check_exact(m, walker, &w);
        }
        fl_sweep_free(fresh);
    }
    printf("  deforming (%d frames, noise %g): updated hierarchy %zu distances, fresh %zu\n",
           frames, noise, updated_cost, fresh_cost);
    free(rest);
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
}

static void test_sweep_deforming_torus_stays_exact(void)
{
    fl_mesh m = make_torus(40, 20);
    check_deforming(&m, 12, 0.0, 0.15);
    fl_mesh_free(&m);
}

/* Large, non-smooth motion (noise of a third of the tube radius): slower, still exact. */
static void test_sweep_large_deformation_stays_exact(void)
{
    fl_mesh m = make_torus(30, 12);
    check_deforming(&m, 6, 0.1, 1.0);
    fl_mesh_free(&m);
}

static void test_sweep_deforming_degenerate_mesh_stays_exact(void)
{
    fl_mesh m = make_messy();
    check_deforming(&m, 8, 0.05, 0.3);
    fl_mesh_free(&m);
}

/* A random rotation (from a random unit quaternion) and translation. */
static fl_sweep_pose random_pose(double shift)
{
    double q[4], n = 0;
    for (int i = 0; i < 4; i++) {
        q[i] = urand(-1, 1);
        n += q[i] * q[i];
    }
    n = sqrt(n);
    double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    fl_sweep_pose p = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                        2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                        2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)},
                       {urand(-shift, shift), urand(-shift, shift), urand(-shift, shift)}};
    return p;
}

static void apply_pose(const fl_sweep_pose *p, const double *rest, double *xyz, size_t nv)
{
    for (size_t v = 0; v < nv; v++)
        for (int i = 0; i < 3; i++)
            xyz[3 * v + i] = p->r[3 * i] * rest[3 * v] + p->r[3 * i + 1] * rest[3 * v + 1] +
                             p->r[3 * i + 2] * rest[3 * v + 2] + p->t[i];
}

/* §5.3 "a rigid motion does not affect the width of our bounding volumes": a mesh moved
 * rigidly through fl_sweep_update_vertices keeps every radius (each node fits the motion of
 * its corners), and the queries stay exact. */
static void test_sweep_rigidly_updated_mesh_keeps_its_radii(void)
{
    fl_mesh m = make_torus(30, 15);
    fl_error err;
    fl_sweep *s = NULL;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    if (!s) return;
    double *eps = malloc(s->node_count * sizeof *eps);
    double *rest = malloc(3 * m.vertex_count * sizeof *rest);
    memcpy(rest, m.xyz, 3 * m.vertex_count * sizeof *rest);
    for (size_t i = 0; i < s->node_count; i++)
        eps[i] = s->nodes[i].eps;
    for (int k = 0; k < 3; k++) {
        fl_sweep_pose pose = random_pose(2);
        apply_pose(&pose, rest, m.xyz, m.vertex_count);
        CHECK_STATUS(fl_sweep_update_vertices(s, m.xyz, &err), FL_OK, &err);
        double grown = 0;
        for (size_t i = 0; i < s->node_count; i++)
            grown = fmax(grown, s->nodes[i].eps - eps[i]);
        CHECK_MSG(grown < 1e-12, "a radius grew by %g", grown);
        check_volumes(s, &m);
        for (int i = 0; i < 60; i++) {
            double q[3];
            fl_closest r;
            random_query(&m, i, q);
            CHECK_STATUS(fl_sweep_closest(s, q, 1, 0, &r, &err), FL_OK, &err);
            check_exact(&m, q, &r);
        }
    }
    free(rest);
    free(eps);
    fl_sweep_free(s);
    fl_mesh_free(&m);
}

/* §5.2: the hierarchy of the rest shape answers for the shape in any rigid pose, exactly as
 * brute force over the moved triangles. */
static void test_sweep_posed_queries_match_brute_force(void)
{
    fl_mesh m = make_torus(40, 20);
    fl_error err;
    fl_sweep *s = NULL;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    if (!s) return;
    fl_mesh moved = mesh_alloc(m.vertex_count, m.triangle_count);
    memcpy(moved.tri, m.tri, 3 * m.triangle_count * sizeof *m.tri);
    for (int k = 0; k < 8; k++) {
        fl_sweep_pose pose = random_pose(3);
        apply_pose(&pose, m.xyz, moved.xyz, m.vertex_count);
        double q[3 * 50];
        for (int i = 0; i < 50; i++)
            random_query(&moved, i, q + 3 * i);
        fl_closest r[50];
        CHECK_STATUS(fl_sweep_closest_posed(s, &pose, q, 50, 0, r, &err), FL_OK, &err);
        for (int i = 0; i < 50; i++)
            check_exact(&moved, q + 3 * i, r + i);
    }
    fl_mesh_free(&moved);
    fl_sweep_free(s);
    fl_mesh_free(&m);
}

/* §5.2 through a cursor: a slowly turning and drifting mesh, queried at a fixed point each
 * frame, is exact every frame and, thanks to the kept queue, under half the work (distances +
 * box distances, sweep_work.h) of queries from the root. */
static void test_sweep_rigidly_moving_mesh_cursor_is_exact_and_cheaper(void)
{
    fl_mesh m = make_torus(40, 20);
    fl_error err;
    fl_sweep *s = NULL;
    fl_sweep_cursor *cur = NULL;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    if (!cur) return;
    fl_mesh moved = mesh_alloc(m.vertex_count, m.triangle_count);
    memcpy(moved.tri, m.tri, 3 * m.triangle_count * sizeof *m.tri);
    const double q[3] = {1.1, 0.35, 0.3};
    size_t kept = 0, fresh = 0;
    for (int f = 0; f < 200; f++) {
        double a = 0.004 * f, ca = cos(a), sa = sin(a);
        fl_sweep_pose pose = {{ca, -sa, 0, sa, ca, 0, 0, 0, 1}, {0.001 * f, 0, -0.0005 * f}};
        apply_pose(&pose, m.xyz, moved.xyz, m.vertex_count);
        fl_closest r, rf;
        size_t boxes = fl_sweep_cursor_box_tests(cur);
        CHECK_STATUS(fl_sweep_cursor_closest_posed(cur, &pose, q, 0, &r, &err), FL_OK, &err);
        check_exact(&moved, q, &r);
        CHECK_STATUS(fl_sweep_closest_posed(s, &pose, q, 1, 0, &rf, &err), FL_OK, &err);
        CHECK_NEAR(r.distance, rf.distance, 1e-13);
        kept += r.visited + fl_sweep_cursor_box_tests(cur) - boxes;
        fresh += sweep_fresh_work(s, &pose, q, &rf);
        CHECK_NEAR(r.distance, rf.distance, 1e-13);
    }
    printf("  rigid motion, 200 frames: kept queue %zu work, from the root %zu\n", kept, fresh);
    CHECK_MSG(2 * kept < fresh, "kept %zu vs fresh %zu", kept, fresh);
    fl_mesh_free(&moved);
    fl_sweep_cursor_free(cur);
    fl_sweep_free(s);
    fl_mesh_free(&m);
}

/* A 2D polyline (closed noisy circle) in a planar pose against brute force over its moved
 * segments. */
static void test_sweep_posed_polyline_matches_brute_force(void)
{
    enum { N = 300 };
    double pts[2 * N], moved[3 * N];
    for (int i = 0; i < N; i++) {
        double a = 6.283185307179586 * i / N, r = 1 + urand(-0.05, 0.05);
        pts[2 * i] = r * cos(a);
        pts[2 * i + 1] = r * sin(a);
    }
    fl_error err;
    fl_sweep *s = NULL;
    CHECK_STATUS(fl_sweep_polyline_build(pts, N, 2, 1, NULL, &s, &err), FL_OK, &err);
    if (!s) return;
    double a = 0.7, ca = cos(a), sa = sin(a);
    fl_sweep_pose pose = {{ca, -sa, 0, sa, ca, 0, 0, 0, 1}, {2.5, -1, 0}};
    for (int i = 0; i < N; i++) {
        moved[3 * i] = ca * pts[2 * i] - sa * pts[2 * i + 1] + 2.5;
        moved[3 * i + 1] = sa * pts[2 * i] + ca * pts[2 * i + 1] - 1;
        moved[3 * i + 2] = 0;
    }
    for (int k = 0; k < 100; k++) {
        double q[2] = {urand(0, 5), urand(-3.5, 1.5)}, q3[3] = {q[0], q[1], 0};
        fl_closest r;
        CHECK_STATUS(fl_sweep_closest_posed(s, &pose, q, 1, 0, &r, &err), FL_OK, &err);
        ld best = INFINITY;
        for (size_t i = 0; i < N; i++) {
            ld d = oracle_polyline_element(moved, N, i, q3);
            best = d < best ? d : best;
        }
        CHECK_NEAR(r.distance, (double)best, 1e-12 * 8);
        CHECK(r.element < N);
        if (r.element < N)
            CHECK_NEAR((double)oracle_polyline_element(moved, N, r.element, q3), (double)best,
                       1e-12 * 8);
        CHECK(r.point[2] == 0);
        CHECK_NEAR(hypot(r.point[0] - q[0], r.point[1] - q[1]), r.distance, 1e-12 * 8);
    }
    fl_sweep_free(s);
}

static void test_sweep_dynamic_rejects_bad_input(void)
{
    fl_mesh m = make_torus(8, 4);
    fl_error err;
    fl_sweep *s = NULL, *line = NULL;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    double pts[6] = {0, 0, 1, 0, 1, 1};
    CHECK_STATUS(fl_sweep_polyline_build(pts, 3, 2, 0, NULL, &line, &err), FL_OK, &err);
    if (!s || !line) return;
    CHECK_STATUS(fl_sweep_update_vertices(line, pts, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_sweep_update_vertices(s, NULL, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_sweep_update_vertices(NULL, m.xyz, &err), FL_ERR_USAGE, &err);
    /* A bad coordinate leaves the hierarchy as it was. */
    double keep = m.xyz[7];
    m.xyz[7] = NAN;
    CHECK_STATUS(fl_sweep_update_vertices(s, m.xyz, &err), FL_ERR_INPUT, &err);
    m.xyz[7] = 1e151;
    CHECK_STATUS(fl_sweep_update_vertices(s, m.xyz, &err), FL_ERR_INPUT, &err);
    m.xyz[7] = keep;
    double q[3] = {0.3, 0.2, 0.1};
    fl_closest r;
    CHECK_STATUS(fl_sweep_closest(s, q, 1, 0, &r, &err), FL_OK, &err);
    check_exact(&m, q, &r);

    fl_sweep_pose pose = {{1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}};
    CHECK_STATUS(fl_sweep_closest_posed(s, &pose, q, 1, 0, &r, &err), FL_OK, &err);
    check_exact(&m, q, &r);
    pose.r[0] = 2; /* a scaling is not rigid */
    CHECK_STATUS(fl_sweep_closest_posed(s, &pose, q, 1, 0, &r, &err), FL_ERR_INPUT, &err);
    pose.r[0] = 1 + 1e-9;
    CHECK_STATUS(fl_sweep_closest_posed(s, &pose, q, 1, 0, &r, &err), FL_ERR_INPUT, &err);
    pose.r[0] = NAN;
    CHECK_STATUS(fl_sweep_closest_posed(s, &pose, q, 1, 0, &r, &err), FL_ERR_INPUT, &err);
    pose.r[0] = 1;
    pose.t[1] = INFINITY;
    CHECK_STATUS(fl_sweep_closest_posed(s, &pose, q, 1, 0, &r, &err), FL_ERR_INPUT, &err);
    pose.t[1] = 0;
    q[0] = NAN;
    CHECK_STATUS(fl_sweep_closest_posed(s, &pose, q, 1, 0, &r, &err), FL_ERR_USAGE, &err);
    q[0] = 0;
    CHECK_STATUS(fl_sweep_closest_posed(s, NULL, q, 1, 0, &r, &err), FL_ERR_USAGE, &err);
    /* A 2D shape may only turn in its plane. */
    fl_sweep_pose tilt = {{1, 0, 0, 0, 0, -1, 0, 1, 0}, {0, 0, 0}};
    CHECK_STATUS(fl_sweep_closest_posed(line, &tilt, q, 1, 0, &r, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_sweep_closest_posed(s, &tilt, q, 1, 0, &r, &err), FL_OK, &err);
    fl_sweep_free(line);
    fl_sweep_free(s);
    fl_mesh_free(&m);
}

FL_TEST_MAIN(FL_TEST_CASE(test_sweep_deforming_torus_stays_exact),
             FL_TEST_CASE(test_sweep_large_deformation_stays_exact),
             FL_TEST_CASE(test_sweep_deforming_degenerate_mesh_stays_exact),
             FL_TEST_CASE(test_sweep_rigidly_updated_mesh_keeps_its_radii),
             FL_TEST_CASE(test_sweep_posed_queries_match_brute_force),
             FL_TEST_CASE(test_sweep_rigidly_moving_mesh_cursor_is_exact_and_cheaper),
             FL_TEST_CASE(test_sweep_posed_polyline_matches_brute_force),
             FL_TEST_CASE(test_sweep_dynamic_rejects_bad_input))
