/* Key-frame deformation (Guéziec §5.3, first method): the hierarchy's bases and radii are
 * recorded per key frame and interpolated, with the correction term of keyframes.c, at any
 * time in between. Checked at many intermediate times against brute force over every triangle
 * of the interpolated mesh (sweep_oracle.h), the volume invariant on every node, and through a
 * cursor on a coherent walk while the mesh moves. */
#include <stdint.h>

#include "fl_test.h"
#include "mesh_answer_check.h"
#include "sweep_volume_check.h"
#include "test_collapse_meshes.h"

static double kf_rand(double lo, double hi)
{
    return cm_rand(lo, hi);
}

/* Frame f of a deformation of the rest shape: f = 0 is the rest shape; then a wave and a twist
 * growing with f, every third frame a large random jitter, every fourth a turn by 90 degrees
 * about x with a stretch (not locally rigid, and large between consecutive frames). */
static void make_frame(const double *rest, double *out, size_t nv, int f, double size)
{
    for (size_t v = 0; v < nv; v++) {
        const double *p = rest + 3 * v;
        double *q = out + 3 * v;
        if (f == 0) {
            q[0] = p[0], q[1] = p[1], q[2] = p[2];
            continue;
        }
        double a = 0.5 * f * p[2] / size, ca = cos(a), sa = sin(a);
        q[0] = ca * p[0] - sa * p[1];
        q[1] = sa * p[0] + ca * p[1];
        q[2] = p[2] + 0.3 * size * sin(3 * p[0] / size + f);
        if (f % 3 == 0)
            for (int c = 0; c < 3; c++)
                q[c] += kf_rand(-0.3, 0.3) * size;
        if (f % 4 == 0) {
            double y = q[1], z = q[2];
            q[1] = -2 * z, q[2] = y;
        }
    }
}

static double *make_frames(const fl_mesh *m, int frames)
{
    double size = mesh_scale(m);
    double *xyz = malloc((size_t)frames * 3 * m->vertex_count * sizeof *xyz);
    for (int f = 0; f < frames; f++)
        make_frame(m->xyz, xyz + (size_t)f * 3 * m->vertex_count, m->vertex_count, f, size);
    return xyz;
}

/* A query near the current mesh, far from it, or on one of its triangles. */
static void random_query(const fl_mesh *m, int kind, double *p)
{
    double s = mesh_scale(m);
    if (kind % 3 == 0) {
        for (int c = 0; c < 3; c++)
            p[c] = kf_rand(-1.2 * s, 1.2 * s);
    } else if (kind % 3 == 1) {
        for (int c = 0; c < 3; c++)
            p[c] = kf_rand(-1000 * s, 1000 * s);
    } else {
        size_t t = (size_t)(fl_test_rand01(&cm_rng) * (double)m->triangle_count);
        if (t >= m->triangle_count) t = m->triangle_count - 1;
        double u = fl_test_rand01(&cm_rng), w = fl_test_rand01(&cm_rng) * (1 - u);
        for (int c = 0; c < 3; c++)
            p[c] = (1 - u - w) * oracle_vertex(m->xyz, m->tri, t, 0)[c] +
                   u * oracle_vertex(m->xyz, m->tri, t, 1)[c] +
                   w * oracle_vertex(m->xyz, m->tri, t, 2)[c];
    }
}

/* Sets the time, checks every volume and nq queries against brute force on the mesh the key
 * frames give at that time (into `now`, which shares the triangles). */
static void check_time(fl_sweep_keyframes *kf, fl_mesh *now, double t, int nq)
{
    fl_error err;
    CHECK_STATUS(fl_sweep_keyframes_set_time(kf, t, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_keyframes_vertices(kf, now->xyz, &err), FL_OK, &err);
    const fl_sweep *s = fl_sweep_keyframes_sweep(kf);
    check_volumes(s, now);
    for (int i = 0; i < nq; i++) {
        double q[3];
        fl_closest r;
        random_query(now, i, q);
        CHECK_STATUS(fl_sweep_closest(s, q, 1, 0, &r, &err), FL_OK, &err);
        check_exact(now, q, &r);
    }
}

/* Exact answers at integer and random intermediate times, and at the key frames the vertices
 * are the frames themselves. */
static void check_mesh_keyframes(fl_mesh *m, int frames, int times, int nq)
{
    double *xyz = make_frames(m, frames);
    fl_error err;
    fl_sweep_keyframes *kf = NULL;
    CHECK_STATUS(fl_sweep_keyframes_new(m, xyz, (size_t)frames, NULL, &kf, &err), FL_OK, &err);
    if (!kf) {
        free(xyz);
        return;
    }
    fl_mesh now = {m->vertex_count, malloc(3 * m->vertex_count * sizeof(double)),
                   m->triangle_count, m->tri};
    for (int f = 0; f < frames; f++) {
        check_time(kf, &now, f, nq);
        CHECK(memcmp(now.xyz, xyz + (size_t)f * 3 * m->vertex_count,
                     3 * m->vertex_count * sizeof(double)) == 0);
    }
    for (int i = 0; i < times; i++)
        check_time(kf, &now, kf_rand(0, frames - 1), nq);
    check_time(kf, &now, 0.5, nq); /* the largest correction, s(1-s) = 1/4 */
    free(now.xyz);
    fl_sweep_keyframes_free(kf);
    free(xyz);
}

static void test_keyframes_torus_exact_at_intermediate_times(void)
{
    fl_mesh m = cm_noisy_torus(40, 20, 0.1);
    check_mesh_keyframes(&m, 6, 18, 20);
    cm_free(&m);
}

static void test_keyframes_messy_mesh_and_soup_exact(void)
{
    fl_mesh m = cm_messy(10);
    check_mesh_keyframes(&m, 5, 15, 20);
    cm_free(&m);
    fl_mesh soup = cm_soup(200, 0.05);
    check_mesh_keyframes(&soup, 5, 12, 20);
    cm_free(&soup);
}

/* Degenerate key frames: every triangle collapsed onto a line, all vertices on one point,
 * and half the vertices snapped together (duplicates), between ordinary frames. */
static void test_keyframes_degenerate_frames_exact(void)
{
    fl_mesh m = cm_noisy_torus(24, 12, 0.1);
    size_t nv = m.vertex_count, per = 3 * nv;
    double *xyz = malloc(5 * per * sizeof *xyz);
    make_frame(m.xyz, xyz, nv, 0, 1.35);
    for (size_t v = 0; v < nv; v++) {
        const double *p = m.xyz + 3 * v;
        double *line = xyz + per + 3 * v, *point = xyz + 2 * per + 3 * v;
        double *snap = xyz + 3 * per + 3 * v, *last = xyz + 4 * per + 3 * v;
        line[0] = p[0], line[1] = 0.5 * p[0], line[2] = -p[0];
        point[0] = 0.25, point[1] = -0.5, point[2] = 1;
        for (int c = 0; c < 3; c++) {
            snap[c] = v % 2 ? 0.1 : p[c] * 2;
            last[c] = p[c] + 0.5 * sin(7.0 * (double)v + c);
        }
    }
    fl_error err;
    fl_sweep_keyframes *kf = NULL;
    CHECK_STATUS(fl_sweep_keyframes_new(&m, xyz, 5, NULL, &kf, &err), FL_OK, &err);
    if (kf) {
        fl_mesh now = {nv, malloc(per * sizeof(double)), m.triangle_count, m.tri};
        for (int i = 0; i <= 24; i++)
            check_time(kf, &now, 4.0 * i / 24, 15);
        for (int i = 0; i < 20; i++)
            check_time(kf, &now, kf_rand(0, 4), 15);
        free(now.xyz);
    }
    fl_sweep_keyframes_free(kf);
    free(xyz);
    cm_free(&m);
}

/* A coherent stream through one cursor while the mesh moves in small time steps (§5.1/§5.2):
 * exact at every step, forwards and backwards in time. */
static void test_keyframes_cursor_walk_exact(void)
{
    fl_mesh m = cm_noisy_torus(32, 16, 0.1);
    double *xyz = make_frames(&m, 4);
    fl_error err;
    fl_sweep_keyframes *kf = NULL;
    fl_sweep_cursor *cur = NULL;
    CHECK_STATUS(fl_sweep_keyframes_new(&m, xyz, 4, NULL, &kf, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_cursor_new(fl_sweep_keyframes_sweep(kf), &cur, &err), FL_OK, &err);
    fl_mesh now = {m.vertex_count, malloc(3 * m.vertex_count * sizeof(double)), m.triangle_count,
                   m.tri};
    double q[3] = {1.4, 0, 0.2};
    for (int step = 0; step < 300; step++) {
        double t = step < 200 ? 3.0 * step / 200 : 3.0 * (300 - step) / 100;
        CHECK_STATUS(fl_sweep_keyframes_set_time(kf, t, &err), FL_OK, &err);
        CHECK_STATUS(fl_sweep_keyframes_vertices(kf, now.xyz, &err), FL_OK, &err);
        double a = 0.03 * step;
        q[0] = 1.4 * cos(a), q[1] = 1.4 * sin(a), q[2] = 0.2 * sin(3 * a);
        fl_closest r;
        CHECK_STATUS(fl_sweep_cursor_closest(cur, q, 0, &r, &err), FL_OK, &err);
        check_exact(&now, q, &r);
        if (step % 7 == 0) { /* and a query within a tolerance: the interval brackets it */
            CHECK_STATUS(fl_sweep_cursor_closest(cur, q, 0.05, &r, &err), FL_OK, &err);
            double bf = (double)brute_distance(&now, q), tol = 1e-12 * (mesh_scale(&now) + 2);
            CHECK(r.lower <= bf + tol && bf <= r.upper + tol);
        }
    }
    free(now.xyz);
    fl_sweep_cursor_free(cur);
    fl_sweep_keyframes_free(kf);
    free(xyz);
    cm_free(&m);
}

/* k-nearest and within-r on the interpolated mesh agree with the brute-force distances. */
static void test_keyframes_knearest_matches_brute_force(void)
{
    fl_mesh m = cm_noisy_torus(20, 10, 0.1);
    double *xyz = make_frames(&m, 3);
    fl_error err;
    fl_sweep_keyframes *kf = NULL;
    CHECK_STATUS(fl_sweep_keyframes_new(&m, xyz, 3, NULL, &kf, &err), FL_OK, &err);
    fl_mesh now = {m.vertex_count, malloc(3 * m.vertex_count * sizeof(double)), m.triangle_count,
                   m.tri};
    for (int i = 0; i < 10 && kf; i++) {
        CHECK_STATUS(fl_sweep_keyframes_set_time(kf, kf_rand(0, 2), &err), FL_OK, &err);
        CHECK_STATUS(fl_sweep_keyframes_vertices(kf, now.xyz, &err), FL_OK, &err);
        double q[3];
        random_query(&now, i, q);
        uint32_t el[5];
        double d[5];
        size_t found = 0;
        CHECK_STATUS(fl_sweep_knearest(fl_sweep_keyframes_sweep(kf), q, 5, el, d, &found, &err),
                     FL_OK, &err);
        CHECK(found == 5);
        ld best[5] = {INFINITY, INFINITY, INFINITY, INFINITY, INFINITY};
        for (size_t t = 0; t < now.triangle_count; t++) {
            ld x = oracle_mesh_element(now.xyz, now.tri, t, q);
            for (int k = 0; k < 5; k++)
                if (x < best[k]) {
                    ld tmp = best[k];
                    best[k] = x, x = tmp;
                }
        }
        double tol = 1e-12 * (mesh_scale(&now) + fabs(q[0]) + fabs(q[1]) + fabs(q[2]));
        for (int k = 0; k < 5; k++)
            CHECK_NEAR(d[k], (double)best[k], tol);
    }
    free(now.xyz);
    fl_sweep_keyframes_free(kf);
    free(xyz);
    cm_free(&m);
}

static void test_keyframes_single_frame_and_bad_input(void)
{
    fl_mesh m = cm_noisy_torus(8, 6, 0.1);
    fl_error err;
    fl_sweep_keyframes *kf = NULL;
    size_t per = 3 * m.vertex_count;
    CHECK_STATUS(fl_sweep_keyframes_new(&m, m.xyz, 1, NULL, &kf, &err), FL_OK, &err);
    fl_mesh now = {m.vertex_count, malloc(per * sizeof(double)), m.triangle_count, m.tri};
    check_time(kf, &now, 0, 20);
    CHECK_STATUS(fl_sweep_keyframes_set_time(kf, 0.5, &err), FL_ERR_INPUT, &err);
    fl_sweep_keyframes_free(kf);
    kf = NULL;
    double *xyz = make_frames(&m, 2);
    CHECK_STATUS(fl_sweep_keyframes_new(&m, xyz, 2, NULL, &kf, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_keyframes_set_time(kf, 0.25, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_keyframes_set_time(kf, NAN, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_sweep_keyframes_set_time(kf, -1e-9, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_sweep_keyframes_set_time(kf, 1.5, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_sweep_keyframes_set_time(kf, INFINITY, &err), FL_ERR_INPUT, &err);
    /* a rejected time leaves the mesh where it was */
    CHECK_STATUS(fl_sweep_keyframes_vertices(kf, now.xyz, &err), FL_OK, &err);
    for (size_t i = 0; i < per; i++)
        CHECK(now.xyz[i] == 0.75 * xyz[i] + 0.25 * xyz[per + i]);
    CHECK_STATUS(fl_sweep_keyframes_set_time(NULL, 0, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_sweep_keyframes_vertices(kf, NULL, &err), FL_ERR_USAGE, &err);
    CHECK(fl_sweep_keyframes_sweep(NULL) == NULL);
    fl_sweep_keyframes_free(kf);
    fl_sweep_keyframes_free(NULL);
    fl_sweep_keyframes *bad = (fl_sweep_keyframes *)&m;
    CHECK_STATUS(fl_sweep_keyframes_new(&m, xyz, 0, NULL, &bad, &err), FL_ERR_INPUT, &err);
    CHECK(bad == NULL);
    CHECK_STATUS(fl_sweep_keyframes_new(NULL, xyz, 2, NULL, &bad, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_sweep_keyframes_new(&m, NULL, 2, NULL, &bad, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_sweep_keyframes_new(&m, xyz, 2, NULL, NULL, &err), FL_ERR_USAGE, &err);
    double keep = xyz[per + 4];
    double poison[4] = {NAN, INFINITY, -INFINITY, 1e300};
    for (int i = 0; i < 4; i++) {
        xyz[per + 4] = poison[i];
        CHECK_STATUS(fl_sweep_keyframes_new(&m, xyz, 2, NULL, &bad, &err), FL_ERR_INPUT, &err);
        CHECK(bad == NULL);
    }
    xyz[per + 4] = keep;
    m.tri[5] = (uint32_t)m.vertex_count; /* an index out of range: fl_sweep_build's rules */
    CHECK_STATUS(fl_sweep_keyframes_new(&m, xyz, 2, NULL, &bad, &err), FL_ERR_INPUT, &err);
    CHECK(bad == NULL);
    free(now.xyz);
    free(xyz);
    cm_free(&m);
}

FL_TEST_MAIN(FL_TEST_CASE(test_keyframes_torus_exact_at_intermediate_times),
             FL_TEST_CASE(test_keyframes_messy_mesh_and_soup_exact),
             FL_TEST_CASE(test_keyframes_degenerate_frames_exact),
             FL_TEST_CASE(test_keyframes_cursor_walk_exact),
             FL_TEST_CASE(test_keyframes_knearest_matches_brute_force),
             FL_TEST_CASE(test_keyframes_single_frame_and_bad_input))
