/* Skin surface meshes of ball sets (Cheng & Tan §6.1): the mesh is closed, manifold and
 * oriented, its vertices lie on skin^t(B) as computed by an independent oracle from the
 * definition, and its Euler characteristic is twice that of the union of balls (the skin body
 * is homeomorphic to the union, Theorem 15; a compact 3-manifold's boundary has twice its
 * Euler characteristic). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "fl_test.h"
#include "skin_rng.h"
#include "skin_oracle.h"

static uint64_t rng_state = 0x9e3779b97f4a7c15ULL;

static double rnd(void)
{
    return skin_rng_next(&rng_state);
}

/* Meshes the balls and checks the topology; returns the mesh (free it) or zeroed on failure. */
static fl_mesh mesh_and_check(const double *xyzw, size_t n, double t, long long expect_euler,
                              const char *what)
{
    fl_mesh mesh = {0};
    fl_error err;
    fl_skin_options opt = {0};
    opt.t = t;
    fl_skin_stats stats;
    CHECK_STATUS(fl_skin_mesh(xyzw, n, &opt, &mesh, &stats, &err), FL_OK, &err);
    fl_mesh_report rep;
    fl_mesh_check_options copt = {0};
    copt.skip_self_intersections = 1;
    CHECK_STATUS(fl_mesh_check(&mesh, &copt, &rep, &err), FL_OK, &err);
    CHECK_MSG(rep.closed && rep.manifold && rep.oriented, "%s: closed %d manifold %d oriented %d",
              what, rep.closed, rep.manifold, rep.oriented);
    CHECK_MSG(rep.euler == expect_euler, "%s: euler %lld, expected %lld", what, rep.euler,
              expect_euler);
    CHECK_MSG(rep.volume > 0, "%s: enclosed volume %g should be positive (outward)", what,
              rep.volume);
    CHECK_MSG(stats.max_vertex_offset < 1e-9 * stats.cell * 50, "%s: vertex offset %g", what,
              stats.max_vertex_offset);
    fl_mesh_report_free(&rep);
    return mesh;
}

/* About `samples` vertices spread over the mesh are on the skin by the oracle:
 * |G| / |grad G| <= 1e-9 of the scale of the configuration. */
static void check_vertices_on_skin(const fl_mesh *m, const double *xyzw, int n, double t,
                                   double scale, size_t samples)
{
    double worst = 0;
    size_t stride = m->vertex_count / samples + 1;
    for (size_t i = 0; i < m->vertex_count; i += stride) {
        double off = skin_oracle_offset(xyzw, n, t, m->xyz + 3 * i, 1e-5 * scale);
        if (!(off <= worst)) worst = off;
    }
    CHECK_MSG(worst <= 1e-9 * scale, "worst vertex offset %g (scale %g)", worst, scale);
}

static void test_single_ball_skin_is_sphere_of_radius_sqrt_t_r(void)
{
    const double ts[2] = {0.5, 0.3};
    for (int k = 0; k < 2; k++) {
        double ball[4] = {1.5, -2.0, 0.25, 4.0}; /* r = 2 */
        fl_mesh m = mesh_and_check(ball, 1, ts[k], 2, "single ball");
        double want = sqrt(ts[k]) * 2.0, worst = 0;
        for (size_t i = 0; i < m.vertex_count; i++) {
            const double *v = m.xyz + 3 * i;
            double d = sqrt((v[0] - 1.5) * (v[0] - 1.5) + (v[1] + 2) * (v[1] + 2) +
                            (v[2] - 0.25) * (v[2] - 0.25));
            worst = fmax(worst, fabs(d - want) / want);
        }
        CHECK_MSG(worst <= 1e-9, "relative radius error %g", worst);
        CHECK(m.vertex_count > 100);
        fl_mesh_free(&m);
    }
}

static void test_two_overlapping_balls_give_one_sphere(void)
{
    double b[8] = {0, 0, 0, 1.0, 1.4, 0.2, -0.1, 0.64};
    fl_mesh m = mesh_and_check(b, 2, 0.5, 2, "two overlapping balls");
    check_vertices_on_skin(&m, b, 2, 0.5, 1.0, 2000);
    fl_mesh_free(&m);
}

static void test_two_separate_balls_give_two_spheres(void)
{
    double b[8] = {0, 0, 0, 1.0, 3.0, 0, 0, 1.0};
    fl_mesh m = mesh_and_check(b, 2, 0.5, 4, "two separate balls");
    fl_mesh_free(&m);
}

/* A necklace of k balls around a circle: a solid torus, Euler characteristic 0 on the skin.
 * With 8 balls the function enumerates subsets, with 14 it uses the regular triangulation. */
static void test_ring_of_balls_is_a_torus(void)
{
    const int ks[2] = {8, 14};
    for (int j = 0; j < 2; j++) {
        int k = ks[j];
        double *b = malloc(4 * (size_t)k * sizeof *b);
        for (int i = 0; i < k; i++) {
            double a = 2 * 3.14159265358979323846 * i / k;
            b[4 * i] = 3 * cos(a);
            b[4 * i + 1] = 3 * sin(a);
            b[4 * i + 2] = 0.05 * (i % 3); /* not all centres in one plane */
            b[4 * i + 3] = pow(1.6 * 3 * sin(3.14159265358979323846 / k), 2);
        }
        fl_mesh m = mesh_and_check(b, (size_t)k, 0.5, 0, "ring");
        check_vertices_on_skin(&m, b, k, 0.5, 3.0, 150);
        fl_mesh_free(&m);
        free(b);
    }
}

/* The skin function against the oracle at random points, for a random ball set that goes
 * through the regular triangulation (more than 8 balls). */
static void test_skin_function_matches_definition(void)
{
    enum { N = 14 };
    double b[4 * N];
    for (int i = 0; i < N; i++) {
        for (int c = 0; c < 3; c++)
            b[4 * i + c] = 4 * rnd();
        b[4 * i + 3] = pow(0.5 + rnd(), 2);
    }
    b[4 * 5 + 3] = -0.3; /* a ball of negative weight still takes part in combinations */
    fl_skin_function *g = NULL;
    fl_error err;
    CHECK_STATUS(fl_skin_function_new(b, N, 0.4, &g, &err), FL_OK, &err);
    if (!g) return;
    int negatives = 0;
    for (int q = 0; q < 400; q++) {
        double x[3] = {4 * rnd(), 4 * rnd(), 4 * rnd()};
        double got = fl_skin_function_value(g, x);
        double want = (double)skin_oracle_value(b, N, 0.4, x);
        if (want <= 0 || got <= 0) {
            negatives += want < 0;
            CHECK_MSG(fabs(got - want) <= 1e-9 * 16, "G(%g,%g,%g) = %.17g, oracle %.17g", x[0],
                      x[1], x[2], got, want);
        } else {
            CHECK_MSG(got >= want * (1 - 1e-12), "positive G below the oracle: %g < %g", got, want);
        }
    }
    CHECK(negatives > 50);
    fl_skin_function_free(g);
}

/* Balls of very different sizes, as in the eps-approximation's B* (a large inner ball among
 * small surface balls and negative ones): the index lists each simplex only near its mixed
 * cell or within its own reach, not within the largest ball's reach, so this checks that no
 * minimiser is missed where it matters. Queries near the skin (where the sign decides the
 * mesh) and anywhere in the box, against the oracle. */
static void test_skin_function_mixed_sizes_matches_definition(void)
{
    enum { N = 12 };
    double b[4 * N];
    b[0] = b[1] = b[2] = 0;
    b[3] = 1.5 * 1.5;
    for (int i = 1; i < N; i++) {
        double u[3], len = 0;
        for (int c = 0; c < 3; c++) {
            u[c] = rnd() - 0.5;
            len += u[c] * u[c];
        }
        len = sqrt(len);
        double rad = 1.5 + 0.4 * rnd();
        for (int c = 0; c < 3; c++)
            b[4 * i + c] = rad * u[c] / len;
        b[4 * i + 3] = i % 6 == 0 ? -0.02 : pow(0.15 + 0.3 * rnd(), 2);
    }
    double t = 0.5;
    fl_skin_function *g = NULL;
    fl_error err;
    CHECK_STATUS(fl_skin_function_new(b, N, t, &g, &err), FL_OK, &err);
    if (!g) return;
    int negatives = 0, near = 0;
    for (int q = 0; q < 400; q++) {
        double x[3];
        if (q % 2) { /* near the big ball's skin sphere (radius sqrt(t) 1.5) or beyond it */
            double u[3], len = 0;
            for (int c = 0; c < 3; c++) {
                u[c] = rnd() - 0.5;
                len += u[c] * u[c];
            }
            double rad = sqrt(t) * 1.5 * (0.8 + 0.6 * rnd());
            for (int c = 0; c < 3; c++)
                x[c] = rad * u[c] / sqrt(len);
        } else {
            for (int c = 0; c < 3; c++)
                x[c] = 5 * rnd() - 2.5;
        }
        double got = fl_skin_function_value(g, x);
        double want = (double)skin_oracle_value(b, N, t, x);
        near += fabs(want) < 0.1;
        if (want <= 0 || got <= 0) {
            negatives += want < 0;
            CHECK_MSG(fabs(got - want) <= 1e-9 * 16, "G(%g,%g,%g) = %.17g, oracle %.17g", x[0],
                      x[1], x[2], got, want);
        } else {
            CHECK_MSG(got >= want * (1 - 1e-12), "positive G below the oracle: %g < %g", got, want);
        }
    }
    CHECK_MSG(negatives > 60 && near > 10, "%d negative, %d near the skin", negatives, near);
    fl_skin_function_free(g);
}

/* Random ball sets: topology from the alpha complex (independent), vertices from the oracle. */
static void test_random_balls_euler_matches_union(void)
{
    for (int rep = 0; rep < 2; rep++) {
        enum { N = 12 };
        double b[4 * N];
        for (int i = 0; i < N; i++) {
            for (int c = 0; c < 3; c++)
                b[4 * i + c] = 4 * rnd();
            b[4 * i + 3] = pow(0.7 + 0.6 * rnd(), 2);
        }
        int ok = 0;
        long long chi = euler_union_oracle(b, N, &ok);
        CHECK(ok);
        fl_mesh m = mesh_and_check(b, N, 0.5, 2 * chi, "random balls");
        check_vertices_on_skin(&m, b, N, 0.5, 4.0, 60);
        fl_mesh_free(&m);
    }
}

static void test_bad_input_is_rejected(void)
{
    fl_mesh m;
    fl_error err;
    double nan_ball[4] = {0, 0, NAN, 1};
    CHECK_STATUS(fl_skin_mesh(nan_ball, 1, NULL, &m, NULL, &err), FL_ERR_INPUT, &err);
    double empty_ball[4] = {0, 0, 0, -1};
    CHECK_STATUS(fl_skin_mesh(empty_ball, 1, NULL, &m, NULL, &err), FL_ERR_INPUT, &err);
    double ball[4] = {0, 0, 0, 1};
    fl_skin_options opt = {0};
    opt.t = 1.0;
    CHECK_STATUS(fl_skin_mesh(ball, 1, &opt, &m, NULL, &err), FL_ERR_USAGE, &err);
    opt.t = 0.5;
    opt.cell = 1e-4;
    opt.max_cubes = 1000;
    CHECK_STATUS(fl_skin_mesh(ball, 1, &opt, &m, NULL, &err), FL_ERR_INPUT, &err);
    CHECK(m.vertex_count == 0 && m.xyz == NULL);
    /* 9 balls with centres in one plane: no regular triangulation */
    double flat[36];
    for (int i = 0; i < 9; i++) {
        flat[4 * i] = i % 3;
        flat[4 * i + 1] = i / 3;
        flat[4 * i + 2] = 0;
        flat[4 * i + 3] = 0.5;
    }
    CHECK_STATUS(fl_skin_mesh(flat, 9, NULL, &m, NULL, &err), FL_ERR_INPUT, &err);
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_single_ball_skin_is_sphere_of_radius_sqrt_t_r),
        FL_TEST_CASE(test_two_overlapping_balls_give_one_sphere),
        FL_TEST_CASE(test_two_separate_balls_give_two_spheres),
        FL_TEST_CASE(test_ring_of_balls_is_a_torus),
        FL_TEST_CASE(test_skin_function_matches_definition),
        FL_TEST_CASE(test_skin_function_mixed_sizes_matches_definition),
        FL_TEST_CASE(test_random_balls_euler_matches_union),
        FL_TEST_CASE(test_bad_input_is_rejected),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}
