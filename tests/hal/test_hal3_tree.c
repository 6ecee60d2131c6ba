/* The 3D flintstone tree (thesis §7.3): the finest level is the input, every level and every
 * adaptive approximation is a closed manifold, every flintstone holds its subtree's triangles,
 * the certified error bounds the surface's distance to the approximation, bad input is named. */
#include "fl_test.h"
#include "hal/hal3_internal.h"
#include "hal3_meshes.h"

#define N_MESHES 6

static fl_mesh test_mesh(int i)
{
    switch (i) {
    case 0:
        return hal3_icosphere(2);
    case 1:
        return hal3_blob(3, 2.0, 1.0, 0.6, 0.0); /* ellipsoid */
    case 2:
        return hal3_blob(2, 1.0, 1.0, 1.0, 0.15); /* noisy sphere */
    case 3:
        return hal3_cube(4);
    case 4:
        return hal3_peanut();
    default:
        return hal3_icosphere(0);
    }
}

static const char *mesh_name[N_MESHES] = {"icosphere2", "ellipsoid", "noisy",
                                          "cube4",      "peanut",    "icosahedron"};

static int build(const fl_mesh *m, fl_hal3 *hal, const char *name)
{
    fl_error err;
    fl_status st = fl_hal3_build(m, NULL, hal, &err);
    CHECK_MSG(st == FL_OK, "%s: %s", name, err.message);
    return st == FL_OK;
}

static void test_hal3_leaves_are_the_original_triangles_once(void)
{
    for (int i = 0; i < N_MESHES; i++) {
        fl_mesh m = test_mesh(i);
        CHECK(m.triangle_count > 0);
        fl_hal3 hal;
        if (!build(&m, &hal, mesh_name[i])) {
            fl_mesh_free(&m);
            continue;
        }
        uint32_t *seen = calloc(m.triangle_count, sizeof(uint32_t));
        size_t leaves = 0;
        for (size_t n = 0; n < hal.node_count; n++) {
            const fl_hal3_node *nd = &hal.nodes[n];
            if (nd->kind != FL_HAL3_LEAF) {
                CHECK(nd->child_count <= 4);
                CHECK(nd->child_count >= 1 || nd->face_count == 0);
                continue;
            }
            leaves++;
            seen[nd->face]++;
            const uint32_t *t = m.tri + 3 * (size_t)nd->face;
            int rot = -1;
            for (int r = 0; r < 3; r++)
                if (t[r] == nd->v[0] && t[(r + 1) % 3] == nd->v[1] && t[(r + 2) % 3] == nd->v[2])
                    rot = r;
            CHECK_MSG(rot >= 0, "%s: leaf %zu corners differ from its triangle", mesh_name[i], n);
        }
        CHECK_EQ_INT(leaves, m.triangle_count);
        for (size_t t = 0; t < m.triangle_count; t++)
            CHECK_EQ_INT(seen[t], 1);
        /* The approximation at the deepest level has the original triangles only. */
        fl_mesh ap;
        double e = -1;
        fl_error err;
        CHECK_STATUS(fl_hal3_approximate_level(&hal, hal.depth, &ap, &e, &err), FL_OK, &err);
        CHECK_EQ_INT(ap.triangle_count, m.triangle_count);
        CHECK(e == 0);
        fl_mesh_free(&ap);
        free(seen);
        fl_hal3_free(&hal);
        fl_mesh_free(&m);
    }
}

static void check_closed(const fl_mesh *ap, const char *what, const char *name, long level)
{
    fl_mesh_report r;
    fl_error err;
    fl_mesh_check_options o = {.skip_self_intersections = 1};
    CHECK_STATUS(fl_mesh_check(ap, &o, &r, &err), FL_OK, &err);
    CHECK_MSG(r.closed && r.oriented, "%s %s %ld: %zu boundary edges, %zu misoriented", name, what,
              level, r.boundary_edges, r.misoriented_edges);
    CHECK_MSG(r.manifold, "%s %s %ld: %zu non-manifold edges, %zu non-manifold vertices", name,
              what, level, r.nonmanifold_edges, r.nonmanifold_vertices);
    fl_mesh_report_free(&r);
}

/* Every level and every adaptive approximation is a closed, oriented manifold (thesis §7.3: the
 * approximations are crack-free; zero boundary, non-manifold and misoriented edges); level 0 is
 * the two triangles v_i v_j v_k and the deepest level the input. */
static void test_hal3_every_level_and_adaptive_cut_is_a_closed_manifold(void)
{
    for (int i = 0; i < N_MESHES; i++) {
        fl_mesh m = test_mesh(i);
        fl_hal3 hal;
        if (!build(&m, &hal, mesh_name[i])) {
            fl_mesh_free(&m);
            continue;
        }
        size_t last = 0;
        for (uint32_t l = 0; l <= hal.depth + 1; l++) {
            fl_mesh ap;
            fl_error err;
            CHECK_STATUS(fl_hal3_approximate_level(&hal, l, &ap, NULL, &err), FL_OK, &err);
            check_closed(&ap, "level", mesh_name[i], (long)l);
            if (l == 0) CHECK_EQ_INT(ap.triangle_count, 2);
            last = ap.triangle_count;
            fl_mesh_free(&ap);
        }
        CHECK_EQ_INT(last, m.triangle_count);
        /* Adaptive cuts at 16 bounds from 2 R down to R / 2^13 (each a different set of
         * nodes): closed too, and certified within the bound. */
        double R = sqrt(hal.ball[3]);
        for (int k = -1; k <= 13; k++) {
            fl_mesh ap;
            fl_error err;
            double bound = ldexp(R, -k), e = -1;
            CHECK_STATUS(fl_hal3_approximate_error(&hal, bound, &ap, &e, NULL, &err), FL_OK,
                         &err);
            check_closed(&ap, "bound 2^-k R, k", mesh_name[i], k);
            CHECK_MSG(e <= bound, "%s: error %g above bound %g", mesh_name[i], e, bound);
            fl_mesh_free(&ap);
        }
        fl_hal3_free(&hal);
        fl_mesh_free(&m);
    }
}

/* Sample points of a triangle: corners, edge points and interior points. */
static void triangle_samples(const double *a, const double *b, const double *c, double *out)
{
    static const double w[10][3] = {{1, 0, 0},
                                    {0, 1, 0},
                                    {0, 0, 1},
                                    {.5, .5, 0},
                                    {0, .5, .5},
                                    {.5, 0, .5},
                                    {1. / 3, 1. / 3, 1. / 3},
                                    {.8, .1, .1},
                                    {.1, .8, .1},
                                    {.1, .1, .8}};
    for (int s = 0; s < 10; s++)
        for (int k = 0; k < 3; k++)
            out[3 * s + k] = w[s][0] * a[k] + w[s][1] * b[k] + w[s][2] * c[k];
}

static void test_hal3_every_flintstone_contains_its_subtree_triangles(void)
{
    for (int i = 0; i < N_MESHES; i++) {
        fl_mesh m = test_mesh(i);
        fl_hal3 hal;
        if (!build(&m, &hal, mesh_name[i])) {
            fl_mesh_free(&m);
            continue;
        }
        uint32_t *stack = malloc((hal.node_count + 1) * sizeof(uint32_t));
        size_t bad = 0;
        for (uint32_t n = 0; n < hal.node_count; n++) {
            size_t top = 0, faces = 0;
            stack[top++] = n;
            while (top > 0) {
                const fl_hal3_node *d = &hal.nodes[stack[--top]];
                for (uint32_t c = 0; c < d->child_count; c++)
                    stack[top++] = d->child_first + c;
                if (d->kind != FL_HAL3_LEAF) continue;
                faces++;
                const uint32_t *t = m.tri + 3 * (size_t)d->face;
                double s[30];
                triangle_samples(m.xyz + 3 * (size_t)t[0], m.xyz + 3 * (size_t)t[1],
                                 m.xyz + 3 * (size_t)t[2], s);
                /* Samples 0-2 are the exact vertices. The others are rounded, so they may
                 * leave the plane of a half-space whose boundary holds the triangle: for a
                 * half-space node they are tested against its ball only (the half-space is
                 * convex and holds the exact vertices). */
                const fl_hal3_node *f = &hal.nodes[n];
                for (int k = 0; k < 10; k++) {
                    int out = !fl_hal3_flintstone_may_contain(&hal, n, s + 3 * k);
                    if (out && k >= 3 && f->kind == FL_HAL3_BALL_HALFSPACE)
                        out = fl_hal3_outside_ball(f->ball[0], s + 3 * k);
                    bad += out;
                }
            }
            CHECK_EQ_INT(faces, hal.nodes[n].face_count);
        }
        CHECK_MSG(bad == 0, "%s: %zu sample points outside their flintstones", mesh_name[i], bad);
        free(stack);
        fl_hal3_free(&hal);
        fl_mesh_free(&m);
    }
}

/* Distance from x to triangle abc by dense barycentric sampling plus the exact corner/edge
 * minimum is not needed: the brute-force bound uses the true minimum over a fine grid, which
 * is >= the true distance, so "true distance <= error" is checked conservatively from above
 * only when the grid distance minus the grid spacing is below the error. */
static double grid_distance(const double *x, const double *a, const double *b, const double *c)
{
    double best = INFINITY;
    const int G = 8;
    for (int i = 0; i <= G; i++)
        for (int j = 0; i + j <= G; j++) {
            double u = (double)i / G, v = (double)j / G, w = 1 - u - v, d2 = 0;
            for (int k = 0; k < 3; k++) {
                double p = u * a[k] + v * b[k] + w * c[k] - x[k];
                d2 += p * p;
            }
            best = fmin(best, d2);
        }
    return sqrt(best);
}

static double longest_edge(const fl_mesh *m)
{
    double e = 0;
    for (size_t t = 0; t < m->triangle_count; t++)
        for (int k = 0; k < 3; k++) {
            const double *p = m->xyz + 3 * (size_t)m->tri[3 * t + k],
                         *q = m->xyz + 3 * (size_t)m->tri[3 * t + (k + 1) % 3];
            e = fmax(e, sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                             (p[2] - q[2]) * (p[2] - q[2])));
        }
    return e;
}

static void test_hal3_adaptive_approximation_is_within_its_certified_error(void)
{
    for (int i = 0; i < N_MESHES; i++) {
        fl_mesh m = test_mesh(i);
        fl_hal3 hal;
        if (!build(&m, &hal, mesh_name[i])) {
            fl_mesh_free(&m);
            continue;
        }
        double scale = sqrt(hal.ball[3]);
        for (int s = 0; s < 4; s++) {
            double bound = scale * (s == 0 ? 0.5 : s == 1 ? 0.1 : s == 2 ? 0.02 : 0.0);
            fl_mesh ap;
            double e = -1;
            uint32_t lv = 0;
            fl_error err;
            CHECK_STATUS(fl_hal3_approximate_error(&hal, bound, &ap, &e, &lv, &err), FL_OK, &err);
            CHECK_MSG(e <= bound, "%s: error %g above bound %g", mesh_name[i], e, bound);
            check_closed(&ap, "bound", mesh_name[i], s);
            if (bound == 0) CHECK_EQ_INT(ap.triangle_count, m.triangle_count);
            /* Every vertex and triangle centroid of the original is within e of the
             * approximation (grid distance overestimates by at most one grid step). */
            double step = longest_edge(&ap) / 8;
            size_t far = 0;
            for (size_t t = 0; t < m.triangle_count && bound > 0; t += 1 + m.triangle_count / 60) {
                double x[3] = {0, 0, 0};
                for (int k = 0; k < 3; k++)
                    for (int c = 0; c < 3; c++)
                        x[c] += m.xyz[3 * (size_t)m.tri[3 * t + k] + c] / 3;
                double d = INFINITY;
                for (size_t u = 0; u < ap.triangle_count; u++)
                    d = fmin(d, grid_distance(x, ap.xyz + 3 * (size_t)ap.tri[3 * u],
                                              ap.xyz + 3 * (size_t)ap.tri[3 * u + 1],
                                              ap.xyz + 3 * (size_t)ap.tri[3 * u + 2]));
                far += d - step > e;
            }
            CHECK_MSG(far == 0, "%s: %zu centroids farther than the certified error %g",
                      mesh_name[i], far, e);
            fl_mesh_free(&ap);
        }
        fl_hal3_free(&hal);
        fl_mesh_free(&m);
    }
}

static void expect_input_error(const fl_mesh *m, const char *needle)
{
    fl_hal3 hal;
    fl_error err;
    memset(&err, 0, sizeof err);
    CHECK_STATUS(fl_hal3_build(m, NULL, &hal, &err), FL_ERR_INPUT, &err);
    CHECK_MSG(strstr(err.message, needle) != NULL, "message '%s' lacks '%s'", err.message, needle);
    CHECK(hal.node_count == 0 && hal.nodes == NULL);
}

static void test_hal3_rejects_surfaces_that_are_not_sphere_like(void)
{
    fl_mesh torus;
    fl_error err;
    CHECK_STATUS(fl_read_mesh(FL_SOURCE_DIR "/data/demo/torus.off", &torus, &err), FL_OK, &err);
    expect_input_error(&torus, "genus 1: the HAL tree needs a sphere-like surface");
    fl_mesh_free(&torus);

    fl_mesh m = hal3_icosphere(1);
    m.triangle_count--; /* a hole */
    expect_input_error(&m, "not closed");
    m.triangle_count++;
    m.xyz[4] = NAN;
    expect_input_error(&m, "not finite");
    fl_mesh_free(&m);

    /* Two tetrahedra sharing one vertex: closed, one component, a non-manifold vertex. */
    double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1};
    uint32_t tri[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 4, 5, 0, 6, 4, 0, 5, 6, 4, 6, 5};
    fl_mesh two = {7, xyz, 8, tri};
    expect_input_error(&two, "not manifold");
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_hal3_leaves_are_the_original_triangles_once),
        FL_TEST_CASE(test_hal3_every_level_and_adaptive_cut_is_a_closed_manifold),
        FL_TEST_CASE(test_hal3_every_flintstone_contains_its_subtree_triangles),
        FL_TEST_CASE(test_hal3_adaptive_approximation_is_within_its_certified_error),
        FL_TEST_CASE(test_hal3_rejects_surfaces_that_are_not_sphere_like),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}
