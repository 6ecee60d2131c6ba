/* FL_G1_AUTO (docs/smooth.md, "Auto"): per connected component the three-split where it
 * measures G1, else the six-split. Checked on meshes built here where the three-split alone
 * is NOT G1 (the meshed cube: vertices on cube edges see their stars almost edge-on and some
 * dependent cubic edges stay inconsistent), with the independent oracle of g1_oracle.h. */
#include "g1_meshes.h"
#include "g1_oracle.h"

static fl_g1_surface build(const fl_mesh *m, int scheme)
{
    fl_g1_surface s;
    fl_error err;
    fl_g1_surface_options o = {.scheme = scheme};
    CHECK_STATUS(fl_g1_surface_build(m, &o, &s, &err), FL_OK, &err);
    return s;
}

/* Every patch corner at a mesh vertex is the vertex with the surface's normal (1e-12), and the
 * surface's normals are unit vectors; returns how many corners were checked. */
static size_t check_interpolation(const fl_mesh *m, const fl_g1_surface *s)
{
    double verr, nerr;
    size_t hits = g1_corner_errors(s, m, NULL, &verr, &nerr, NULL);
    CHECK_MSG(verr <= 1e-12 && nerr <= 1e-12, "vertex error %g, normal error %g", verr, nerr);
    return hits;
}

/* The meshed cube (2 x 2 and 3 x 3 squares a face): the three-split alone has normal jumps of
 * degrees there; auto is G1 to < 1e-7 degrees at 41 points of every micro and macro edge,
 * without folds, and interpolates vertices and normals. */
static void test_auto_is_g1_where_three_split_is_not(void)
{
    for (int n = 2; n <= 3; n++) {
        fl_mesh m = g1_meshed_cube(n);
        fl_g1_surface three = build(&m, FL_G1_THREE_SPLIT), s = build(&m, FL_G1_AUTO);
        size_t flips, unpaired;
        double j3 = g1_max_edge_jump(&three, 40, &flips, &unpaired);
        CHECK_MSG(j3 > 1e-3, "n %d: the three-split is G1 here (%g deg), test mesh useless", n,
                  j3);
        double j = g1_max_edge_jump(&s, 40, &flips, &unpaired);
        CHECK_MSG(j < 1e-7, "n %d: auto jump %g deg", n, j);
        CHECK_EQ_INT(flips, 0);
        CHECK_EQ_INT(unpaired, 0);
        CHECK_EQ_INT(s.six_split_triangles, m.triangle_count);
        CHECK_EQ_INT(s.patch_count, 6 * m.triangle_count);
        CHECK_EQ_INT(check_interpolation(&m, &s), s.patch_count); /* (V, m, O): 1 vertex corner */
        fl_g1_surface_free(&three);
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
}

/* Distance from p to triangle (a, b, c), brute force (Ericson, Real-Time Collision Detection
 * §5.1.5): independent of the library's closest-point queries. */
static double point_triangle_distance(const double *p, const double *a, const double *b,
                                      const double *c)
{
    double ab[3], ac[3], ap[3], q[3];
    for (int d = 0; d < 3; d++) {
        ab[d] = b[d] - a[d];
        ac[d] = c[d] - a[d];
        ap[d] = p[d] - a[d];
    }
#define DOT(x, y) ((x)[0] * (y)[0] + (x)[1] * (y)[1] + (x)[2] * (y)[2])
    double d1 = DOT(ab, ap), d2 = DOT(ac, ap), bp[3], cp[3], u = 0, v = 0;
    for (int d = 0; d < 3; d++) {
        bp[d] = p[d] - b[d];
        cp[d] = p[d] - c[d];
    }
    double d3 = DOT(ab, bp), d4 = DOT(ac, bp), d5 = DOT(ab, cp), d6 = DOT(ac, cp);
    double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
#undef DOT
    if (d1 <= 0 && d2 <= 0) u = v = 0;
    else if (d3 >= 0 && d4 <= d3) u = 1, v = 0;
    else if (d6 >= 0 && d5 <= d6) u = 0, v = 1;
    else if (vc <= 0 && d1 >= 0 && d3 <= 0) u = d1 / (d1 - d3), v = 0;
    else if (vb <= 0 && d2 >= 0 && d6 <= 0) u = 0, v = d2 / (d2 - d6);
    else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        u = 1 - v;
    } else {
        u = vb / (va + vb + vc);
        v = vc / (va + vb + vc);
    }
    for (int d = 0; d < 3; d++)
        q[d] = a[d] + u * ab[d] + v * ac[d] - p[d];
    return sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
}

/* Max distance of the patch points on a grid of 4 segments an edge (auto's grid) from the
 * mesh, by brute force over all triangles. */
static double brute_deviation(const fl_mesh *m, const fl_g1_surface *s)
{
    double worst = 0;
    for (size_t p = 0; p < s->patch_count; p++)
        for (int a = 0; a <= 4; a++)
            for (int b = 0; a + b <= 4; b++) {
                double q[3], best = INFINITY;
                fl_g1_patch_eval(s->ctrl + 30 * p, a / 4.0, b / 4.0, (4 - a - b) / 4.0, q, NULL);
                for (size_t t = 0; t < m->triangle_count; t++) {
                    const uint32_t *v = m->tri + 3 * t;
                    best = fmin(best, point_triangle_distance(q, m->xyz + 3 * v[0],
                                                              m->xyz + 3 * v[1],
                                                              m->xyz + 3 * v[2]));
                }
                worst = fmax(worst, best);
            }
    return worst;
}

/* Where both the three-split and the six-split are G1 (octahedron, jittered icospheres), auto returns, bit for bit, the one whose patches stay nearer the mesh (max
 * distance on auto's grid, computed here by brute force). Both outcomes occur among these
 * meshes, so the test fails for a rule that always keeps one scheme. */
static void test_auto_keeps_the_nearer_g1_scheme(void)
{
    fl_mesh ms[3] = {g1_octahedron(), g1_icosphere(1, 0.02, 5), g1_icosphere(2, 0.02, 3)};
    int chose[2] = {0, 0};
    for (int i = 0; i < 3; i++) {
        fl_g1_surface three = build(&ms[i], FL_G1_THREE_SPLIT), six = build(&ms[i], FL_G1_SIX_SPLIT);
        fl_g1_surface s = build(&ms[i], FL_G1_AUTO);
        size_t flips, unpaired;
        CHECK(g1_max_edge_jump(&three, 32, &flips, &unpaired) < 1e-7 && flips == 0);
        CHECK(g1_max_edge_jump(&six, 32, &flips, &unpaired) < 1e-7 && flips == 0);
        double d3 = brute_deviation(&ms[i], &three), d6 = brute_deviation(&ms[i], &six);
        CHECK_MSG(fabs(d3 - d6) > 1e-6 * d3, "mesh %d: deviations too close to decide", i);
        const fl_g1_surface *want = d6 < d3 ? &six : &three;
        chose[d6 < d3]++;
        CHECK_EQ_INT(s.six_split_triangles, d6 < d3 ? ms[i].triangle_count : 0);
        CHECK_EQ_INT(s.patch_count, want->patch_count);
        CHECK(memcmp(s.ctrl, want->ctrl, 30 * s.patch_count * sizeof(double)) == 0);
        CHECK(memcmp(s.corner, want->corner, 3 * s.patch_count * sizeof(uint32_t)) == 0);
        CHECK(g1_max_edge_jump(&s, 40, &flips, &unpaired) < 1e-7 && flips == 0);
        printf("mesh %d: three-split deviation %.4g, six-split %.4g: auto %s\n", i, d3, d6,
               d6 < d3 ? "six-split" : "three-split");
        fl_g1_surface_free(&three);
        fl_g1_surface_free(&six);
        fl_g1_surface_free(&s);
        fl_mesh_free(&ms[i]);
    }
    CHECK_MSG(chose[0] > 0 && chose[1] > 0, "three-split %d, six-split %d times", chose[0],
              chose[1]);
}

/* Two components in one mesh: a meshed cube (needs the six-split) and, shifted away and listed
 * first, an icosphere (the three-split suffices). Each component gets its own scheme, the
 * patches meet only within their component (every patch edge paired, node ids distinct), the
 * whole is G1 and interpolates, and the tessellation is two closed spheres. */
static void test_auto_chooses_per_connected_component(void)
{
    fl_mesh a = g1_icosphere(1, 0.02, 7), b = g1_meshed_cube(2);
    size_t nv = a.vertex_count + b.vertex_count, nt = a.triangle_count + b.triangle_count;
    double *xyz = malloc(3 * nv * sizeof(double));
    uint32_t *tri = malloc(3 * nt * sizeof(uint32_t));
    memcpy(xyz, a.xyz, 3 * a.vertex_count * sizeof(double));
    for (size_t i = 0; i < 3 * b.vertex_count; i++)
        xyz[3 * a.vertex_count + i] = b.xyz[i] + 10;
    memcpy(tri, a.tri, 3 * a.triangle_count * sizeof(uint32_t));
    for (size_t i = 0; i < 3 * b.triangle_count; i++)
        tri[3 * a.triangle_count + i] = b.tri[i] + (uint32_t)a.vertex_count;
    fl_mesh m = g1_mesh_from(xyz, nv, tri, nt);
    fl_g1_surface s = build(&m, FL_G1_AUTO);
    CHECK_EQ_INT(s.six_split_triangles, b.triangle_count);
    CHECK_EQ_INT(s.patch_count, 3 * a.triangle_count + 6 * b.triangle_count);
    CHECK_EQ_INT(s.vertex_count, nv);
    size_t flips, unpaired;
    double j = g1_max_edge_jump(&s, 40, &flips, &unpaired);
    CHECK_MSG(j < 1e-7, "jump %g deg", j);
    CHECK_EQ_INT(flips, 0);
    CHECK_EQ_INT(unpaired, 0);
    /* three-split patches (V, V', O) have two vertex corners, six-split ones (V, m, O) one */
    CHECK_EQ_INT(check_interpolation(&m, &s), 3 * a.triangle_count * 2 + 6 * b.triangle_count);
    /* macro[] names the input triangle: the patch's vertex corners are that triangle's. */
    for (size_t p = 0; p < s.patch_count; p++) {
        const uint32_t *t = m.tri + 3 * (size_t)s.macro[p];
        for (int c = 0; c < 3; c++) {
            uint32_t v = s.corner[3 * p + c];
            if (v < nv) CHECK(v == t[0] || v == t[1] || v == t[2]);
        }
    }
    fl_mesh tm;
    double *nn = NULL;
    fl_error err;
    CHECK_STATUS(fl_g1_surface_tessellate(&s, 2, &tm, &nn, &err), FL_OK, &err);
    fl_mesh_report r;
    fl_mesh_check_options skip = {.skip_self_intersections = 1};
    CHECK_STATUS(fl_mesh_check(&tm, &skip, &r, &err), FL_OK, &err);
    CHECK(r.closed && r.manifold && r.oriented);
    CHECK_EQ_INT(r.duplicate_vertices, 0);
    /* two spheres: V - E + F = 4 with E = 3F/2 */
    CHECK_EQ_INT((long long)tm.vertex_count, (long long)tm.triangle_count / 2 + 4);
    fl_mesh_report_free(&r);
    free(nn);
    fl_mesh_free(&tm);
    fl_g1_surface_free(&s);
    fl_mesh_free(&m);
    free(xyz);
    free(tri);
    fl_mesh_free(&a);
    fl_mesh_free(&b);
}

FL_TEST_MAIN(FL_TEST_CASE(test_auto_is_g1_where_three_split_is_not),
             FL_TEST_CASE(test_auto_keeps_the_nearer_g1_scheme),
             FL_TEST_CASE(test_auto_chooses_per_connected_component))
