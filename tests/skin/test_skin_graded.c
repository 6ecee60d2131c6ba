/* The graded skin mesher (fl_skin_options.grade > 0; src/skin/skin_graded.c) on ball sets
 * whose radii span 100x: the mesh is closed, 2-manifold and outward oriented, its Euler
 * characteristic is twice that of the union of balls (Theorem 15: the skin body is
 * homeomorphic to the union; the union's Euler characteristic comes from the alpha complex in
 * skin_oracle.h, independent of src/skin), and its vertices lie on the skin by the oracle
 * built from the definition. */
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

/* Meshes with the graded grid, checks closed / manifold / oriented / Euler / vertices on the
 * skin at `samples` vertices (|G| / |grad G| by the oracle <= 1e-9 scale). Returns the number
 * of leaves of the octree. */
static size_t graded_check(const double *b, int n, double t, double grade, long long euler,
                           double scale, size_t samples, const char *what)
{
    fl_mesh m = {0};
    fl_error err;
    fl_skin_options opt = {0};
    opt.t = t;
    opt.grade = grade;
    fl_skin_stats st;
    CHECK_STATUS(fl_skin_mesh(b, (size_t)n, &opt, &m, &st, &err), FL_OK, &err);
    fl_mesh_report rep;
    fl_mesh_check_options co = {0};
    co.skip_self_intersections = 1;
    CHECK_STATUS(fl_mesh_check(&m, &co, &rep, &err), FL_OK, &err);
    CHECK_MSG(rep.closed && rep.manifold && rep.oriented, "%s: closed %d manifold %d oriented %d",
              what, rep.closed, rep.manifold, rep.oriented);
    CHECK_MSG(rep.euler == euler, "%s: euler %lld, expected %lld", what, rep.euler, euler);
    CHECK_MSG(rep.volume > 0, "%s: volume %g should be positive (outward)", what, rep.volume);
    fl_mesh_report_free(&rep);
    double worst = 0;
    size_t stride = m.vertex_count / samples + 1;
    for (size_t i = 0; i < m.vertex_count; i += stride) {
        double off = skin_oracle_offset(b, n, t, m.xyz + 3 * i, 1e-5 * st.cell);
        if (!(off <= worst)) worst = off;
    }
    CHECK_MSG(worst <= 1e-9 * scale, "%s: worst vertex offset %g (scale %g)", what, worst, scale);
    fl_mesh_free(&m);
    return st.cubes;
}

/* One ball of radius 1e-2 beside one of radius 1 (100x), overlapping: one sphere. The uniform
 * default grid would need cells of sqrt(t) 0.01 / 4 over the big ball's box, ~2e8 cubes; the
 * graded one refines only near the small ball. */
static void test_small_ball_on_big_ball_is_one_sphere(void)
{
    /* the small ball's centre at distance 1.0041 from the big one's: it sticks out */
    double b[8] = {0, 0, 0, 1.0, 1.004, 0.0137, 0.0091, 1e-4};
    /* two overlapping balls: the union is contractible (the oracle needs 4 centres) */
    size_t leaves = graded_check(b, 2, 0.5, 1.0, 2, 1.0, 200, "small on big");
    double h = 0.25 * sqrt(0.5) * 0.01, uniform = pow(2 * 1.0 / h, 3);
    CHECK_MSG((double)leaves < 0.01 * uniform, "%zu leaves vs %g uniform cubes", leaves,
              uniform);
}

/* A chain of balls shrinking by 0.7 each step from radius 1 to ~0.01 (a horn): one
 * component, Euler 2; the necks between consecutive balls are resolved at every scale. */
static void test_shrinking_chain_is_one_sphere(void)
{
    enum { N = 14 };
    double b[4 * N], x = 0, r = 1;
    for (int i = 0; i < N; i++) {
        b[4 * i] = x;
        b[4 * i + 1] = 0.03 * r * (i % 3);
        b[4 * i + 2] = 0.02 * r * (i % 2);
        b[4 * i + 3] = r * r;
        x += 1.25 * r;
        r *= 0.7;
    }
    int ok = 0;
    long long chi = euler_union_oracle(b, N, &ok);
    CHECK(ok && chi == 1);
    graded_check(b, N, 0.5, 1.0, 2 * chi, 2.0, 100, "shrinking chain");
}

/* Random sets of 14 balls with radii log-uniform in [0.02, 2] (100x): Euler characteristic
 * 2 chi(union) by the alpha-complex oracle. */
static void test_random_balls_with_radii_spanning_100x(void)
{
    for (int rep = 0; rep < 2; rep++) {
        enum { N = 14 };
        double b[4 * N];
        for (int i = 0; i < N; i++) {
            for (int c = 0; c < 3; c++)
                b[4 * i + c] = 5 * rnd();
            double r = 0.02 * pow(100.0, rnd());
            b[4 * i + 3] = r * r;
        }
        int ok = 0;
        long long chi = euler_union_oracle(b, N, &ok);
        CHECK(ok);
        graded_check(b, N, 0.5, 1.0, 2 * chi, 5.0, 60, "random 100x");
    }
}

/* A ring of 12 balls alternating radius 1 and 0.1 placed so the small ones bridge the big ones:
 * a solid torus, Euler 0 (thin bridges: a coarse uniform grid cuts them). */
static void test_ring_with_thin_bridges_is_a_torus(void)
{
    enum { K = 12 };
    double b[4 * K];
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < K; i++) {
        double a = 2 * pi * i / K, rad = 1.5;
        b[4 * i] = rad * cos(a);
        b[4 * i + 1] = rad * sin(a);
        b[4 * i + 2] = 0.01 * (i % 3);
        /* big balls of radius 0.7 at even positions; the chord between neighbours is
         * 2 * 1.5 sin(pi / 12) = 0.776, so a small ball of radius 0.2 at the odd position
         * overlaps both (0.7 + 0.2 > 0.776) and big balls miss each other (1.5 > 1.4) */
        double r = i % 2 ? 0.2 : 0.7;
        b[4 * i + 3] = r * r;
    }
    int ok = 0;
    long long chi = euler_union_oracle(b, K, &ok);
    CHECK(ok && chi == 0);
    graded_check(b, K, 0.5, 1.0, 2 * chi, 3.0, 100, "ring with bridges");
}

static void test_bad_grade_is_rejected(void)
{
    double ball[4] = {0, 0, 0, 1};
    fl_mesh m;
    fl_error err;
    fl_skin_options opt = {0};
    opt.grade = -1;
    CHECK_STATUS(fl_skin_mesh(ball, 1, &opt, &m, NULL, &err), FL_ERR_USAGE, &err);
    opt.grade = NAN;
    CHECK_STATUS(fl_skin_mesh(ball, 1, &opt, &m, NULL, &err), FL_ERR_USAGE, &err);
    opt.grade = 1e-4; /* too fine: more leaves than allowed */
    opt.max_cubes = 5000;
    CHECK_STATUS(fl_skin_mesh(ball, 1, &opt, &m, NULL, &err), FL_ERR_INPUT, &err);
    CHECK(m.vertex_count == 0 && m.xyz == NULL);
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_small_ball_on_big_ball_is_one_sphere),
        FL_TEST_CASE(test_shrinking_chain_is_one_sphere),
        FL_TEST_CASE(test_random_balls_with_radii_spanning_100x),
        FL_TEST_CASE(test_ring_with_thin_bridges_is_a_torus),
        FL_TEST_CASE(test_bad_grade_is_rejected),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}
