/* The uniform skin mesher keeps its grid points in two z-planes of slabs when the visited cubes
 * span a small x-y extent and in hash maps otherwise, and visits only the cubes that can carry
 * a triangle (not far from every ball, not deep inside a shrunk ball). Neither choice may
 * change the mesh: a ball set and the same set next to a translated copy far away (an x-y
 * extent of ~800^2 grid points, beyond the slabs) give meshes whose sizes and Euler
 * characteristics add up exactly (each set's is 2 chi(union of balls) by the alpha-complex
 * oracle), every vertex on the skin by the independent oracle. And the
 * closed-form vertices (the mixed-cell quadric along the edge) are on the skin to rounding. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "fl_test.h"
#include "skin_rng.h"
#include "skin_oracle.h"

static uint64_t rng_state = 0x2545f4914f6cdd1dULL;

static double rnd(void)
{
    return skin_rng_next(&rng_state);
}

enum { N = 12 };

static void random_balls(double *b, int n)
{
    for (int i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++)
            b[4 * i + c] = 3.0 * rnd();
        double r = 0.5 + 0.5 * rnd();
        b[4 * i + 3] = r * r;
    }
}

typedef struct summary {
    size_t v, f;
    long long euler;
    int ok;
} summary;

static summary mesh_summary(const double *b, size_t n, double cell, fl_mesh *keep)
{
    summary s = {0, 0, 0, 0};
    fl_mesh m = {0};
    fl_error err;
    fl_skin_options opt = {0};
    opt.t = 0.5;
    opt.cell = cell;
    fl_skin_stats st;
    CHECK_STATUS(fl_skin_mesh(b, n, &opt, &m, &st, &err), FL_OK, &err);
    fl_mesh_report rep;
    fl_mesh_check_options co = {0};
    co.skip_self_intersections = 1;
    CHECK_STATUS(fl_mesh_check(&m, &co, &rep, &err), FL_OK, &err);
    s.v = m.vertex_count;
    s.f = m.triangle_count;
    s.euler = rep.euler;
    s.ok = rep.closed && rep.manifold && rep.oriented && rep.volume > 0;
    fl_mesh_report_free(&rep);
    if (keep)
        *keep = m;
    else
        fl_mesh_free(&m);
    return s;
}

/* The worst oracle offset over about `samples` vertices of m; a vertex with x >= split is
 * checked against the balls b2 (the far copy), the others against b (the copies are 80 apart,
 * so near one copy the skin is that copy's skin). */
static double worst_offset(const fl_mesh *m, const double *b, const double *b2, double split,
                           size_t samples, double h)
{
    double worst = 0;
    size_t stride = m->vertex_count / samples + 1;
    for (size_t i = 0; i < m->vertex_count; i += stride) {
        const double *v = m->xyz + 3 * i;
        double off = skin_oracle_offset(v[0] < split ? b : b2, N, 0.5, v, 1e-5 * h);
        if (!(off <= worst)) worst = off;
    }
    return worst;
}

static void test_far_copy_adds_up_across_storage_paths(void)
{
    for (int round = 0; round < 2; round++) {
        double b[8 * N];
        random_balls(b, N);
        double h = 0.1; /* K cells of shift put the copy 800 cells away in x and y */
        const double K = 800;
        for (int i = 0; i < N; i++) {
            b[4 * (N + i)] = b[4 * i] + K * h;
            b[4 * (N + i) + 1] = b[4 * i + 1] + K * h;
            b[4 * (N + i) + 2] = b[4 * i + 2];
            b[4 * (N + i) + 3] = b[4 * i + 3];
        }
        summary one = mesh_summary(b, N, h, NULL);
        fl_mesh both_mesh;
        summary both = mesh_summary(b, 2 * N, h, &both_mesh);
        CHECK(one.ok && both.ok);
        CHECK_MSG(both.v == 2 * one.v && both.f == 2 * one.f && both.euler == 2 * one.euler,
                  "round %d: one set V %zu F %zu euler %lld; with the far copy V %zu F %zu "
                  "euler %lld",
                  round, one.v, one.f, one.euler, both.v, both.f, both.euler);
        CHECK(one.v > 1000);
        int ok = 0;
        long long chi = euler_union_oracle(b, N, &ok); /* the skin of one set: 2 chi(union) */
        CHECK_MSG(ok && one.euler == 2 * chi, "round %d: euler %lld, 2 chi(union) %lld", round,
                  one.euler, 2 * chi);
        double worst = worst_offset(&both_mesh, b, b + 4 * N, 0.5 * K * h, 300, h);
        CHECK_MSG(worst <= 1e-9 * 3, "round %d: worst vertex offset %g", round, worst);
        fl_mesh_free(&both_mesh);
    }
}

/* Twelve balls (the regular-triangulation path: labels carry mixed cells, most vertices come
 * from the closed form) at a fine and a coarse cell: every vertex on the skin by the oracle,
 * and the mesh's own estimate max_vertex_offset agrees that the vertices are at rounding
 * distance. */
static void test_closed_form_vertices_are_on_the_skin(void)
{
    double b[4 * N];
    random_balls(b, N);
    const double cells[2] = {0.05, 0.2};
    for (int k = 0; k < 2; k++) {
        fl_mesh m = {0};
        fl_error err;
        fl_skin_options opt = {0};
        opt.t = 0.5;
        opt.cell = cells[k];
        fl_skin_stats st;
        CHECK_STATUS(fl_skin_mesh(b, N, &opt, &m, &st, &err), FL_OK, &err);
        CHECK_MSG(st.max_vertex_offset <= 1e-12 * 3, "cell %g: max_vertex_offset %g", cells[k],
                  st.max_vertex_offset);
        double worst = worst_offset(&m, b, b, HUGE_VAL, 400, cells[k]);
        CHECK_MSG(worst <= 1e-11 * 3, "cell %g: worst vertex offset by the oracle %g", cells[k],
                  worst);
        fl_mesh_free(&m);
    }
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_far_copy_adds_up_across_storage_paths),
        FL_TEST_CASE(test_closed_form_vertices_are_on_the_skin),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}
