/* ε-approximation of a polyhedron by balls and a skin (Cheng & Tan §4-6): the result is checked
 * here independently of the library's own verification: the skin mesh is closed, manifold and
 * has the input's Euler characteristic (fl_mesh_check), every B_perp ball lies inside the object
 * and is farther than orthogonal from every protecting ball (brute force here), no two B_perp
 * balls are equal up to rounding (mirror twins), every protecting ball's radius is <= epsilon
 * (weights <= eps^2, the eps-SAC of §5 step 1), and bad input or a too-small epsilon fails with
 * a clear error instead of running without bound. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"
#include "skin_cube.h"

/* The ball (x, y, z, w) lies in the closed unit cube (convex: its box suffices). Theorem 4:
 * an orthogonal ball of an eps-SAC does not cross the surface, so a B_perp ball whose centre
 * is inside lies inside. (The first version found centres exactly on a face: fl_rt3's
 * orthocentres of the cube's symmetric slivers were rounding noise; docs/skin.md.) */
static int ball_in_cube(const double *b)
{
    double r = sqrt(b[3]);
    for (int c = 0; c < 3; c++)
        if (!(b[c] - r >= -1e-12 && b[c] + r <= 1 + 1e-12 && b[c] > 0 && b[c] < 1)) return 0;
    return 1;
}

/* min over the protecting balls b of pi(p, b) = |p - z_b|^2 - w_p - w_b: a Voronoi vertex's
 * orthogonal ball is orthogonal to its four balls and farther than orthogonal from the others
 * (the regular triangulation's empty-ball property), so this is >= 0 up to rounding. */
static double min_orthogonal_power(const double *p, const fl_balls *b)
{
    double best = HUGE_VAL;
    for (size_t i = 0; i < b->count; i++) {
        const double *q = b->xyzw + 4 * i;
        double d = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                   (p[2] - q[2]) * (p[2] - q[2]) - p[3] - q[3];
        if (d < best) best = d;
    }
    return best;
}

/* The number of pairs of B_perp balls equal up to rounding (centres and weights within 1e-12
 * of the object's size 1 and its square), by brute force. Each is the ball orthogonal to one
 * Voronoi vertex computed from two tetrahedra: a mirror twin. Before they were merged the
 * unit cube's symmetric protecting balls gave hundreds (5e-15 apart), and the regular
 * triangulation of B* had flat tetrahedra around each pair (docs/skin.md, "The bunny"). */
static size_t twin_pairs(const fl_balls *b)
{
    size_t twins = 0;
    for (size_t i = 0; i < b->count; i++)
        for (size_t j = i + 1; j < b->count; j++) {
            const double *p = b->xyzw + 4 * i, *q = b->xyzw + 4 * j;
            twins += fabs(p[0] - q[0]) <= 1e-12 && fabs(p[1] - q[1]) <= 1e-12 &&
                     fabs(p[2] - q[2]) <= 1e-12 && fabs(p[3] - q[3]) <= 1e-12;
        }
    return twins;
}

/* The checks shared by every object: verified, closed 2-manifold sphere within epsilon,
 * protecting radii <= epsilon, B_perp balls inside the object (ball_inside, computed from the
 * object's definition) and power-empty against the protecting balls. */
static void check_approximation(const fl_mesh *m, double eps, int (*ball_inside)(const double *),
                                const char *name)
{
    fl_skin_approx a;
    fl_error err;
    CHECK_STATUS(fl_skin_approx_build(m, eps, NULL, &a, &err), FL_OK, &err);
    CHECK_MSG(a.verified, "%s: not verified: hausdorff %g euler %lld/%lld", name, a.hausdorff[1],
              a.euler, a.euler_input);
    CHECK(a.hausdorff[1] <= eps);
    fl_mesh_report rep;
    fl_mesh_check_options co = {0};
    co.skip_self_intersections = 1;
    CHECK_STATUS(fl_mesh_check(&a.skin, &co, &rep, &err), FL_OK, &err);
    CHECK_MSG(rep.closed && rep.manifold && rep.euler == 2, "%s: closed %d manifold %d euler %lld",
              name, rep.closed, rep.manifold, rep.euler);
    fl_mesh_report_free(&rep);
    for (size_t i = 0; i < a.surface.count; i++)
        CHECK(a.surface.xyzw[4 * i + 3] <= eps * eps);
    size_t outside = 0, not_empty = 0;
    for (size_t i = 0; i < a.perp.count; i++) {
        const double *p = a.perp.xyzw + 4 * i;
        outside += !ball_inside(p);
        not_empty += !(min_orthogonal_power(p, &a.surface) >= -1e-9);
    }
    CHECK_MSG(outside == 0, "%s: %zu B_perp balls not inside", name, outside);
    CHECK_MSG(not_empty == 0, "%s: %zu B_perp balls closer than orthogonal to a protecting ball",
              name, not_empty);
    CHECK(a.perp.count > 0 && a.star.count >= a.perp.count);
    size_t twins = twin_pairs(&a.perp);
    CHECK_MSG(twins == 0, "%s: %zu pairs of B_perp balls equal up to rounding", name, twins);
    fl_skin_approx_free(&a);
}

static void test_cube_is_approximated_within_epsilon(void)
{
    fl_mesh m = skin_cube_mesh();
    check_approximation(&m, 0.5, ball_in_cube, "cube");
}

/* The octahedron |x| + |y| + |z| <= 1: a ball is inside iff its centre's distance to the
 * nearest face plane, (1 - |c|_1) / sqrt(3), is at least its radius. */
static int ball_in_octahedron(const double *b)
{
    double l1 = fabs(b[0]) + fabs(b[1]) + fabs(b[2]);
    return (1 - l1) / sqrt(3.0) >= sqrt(b[3]) - 1e-12;
}

static void test_octahedron_is_approximated_within_epsilon(void)
{
    static const double xyz[] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    static const uint32_t tri[] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                   2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    fl_mesh m = {0};
    m.vertex_count = 6;
    m.triangle_count = 8;
    m.xyz = (double *)xyz;
    m.tri = (uint32_t *)tri;
    check_approximation(&m, 0.6, ball_in_octahedron, "octahedron");
}

static void test_bad_input_fails_cleanly(void)
{
    fl_mesh m = skin_cube_mesh();
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
        FL_TEST_CASE(test_octahedron_is_approximated_within_epsilon),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}
