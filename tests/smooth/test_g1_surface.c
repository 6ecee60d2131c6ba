/* Properties of the three-split surfaces (thesis §9.6) and the macro/PN baseline, measured on
 * closed meshes: octahedron, cube, icosphere, jittered icosphere and the demo torus. */
#include "g1_oracle.h"

enum { MESHES = 5 };

static fl_mesh test_mesh(int i)
{
    fl_mesh m = {0};
    fl_error err;
    switch (i) {
    case 0:
        return g1_octahedron();
    case 1:
        return g1_cube();
    case 2:
        return g1_icosphere(1, 0, 1);
    case 3:
        return g1_icosphere(2, 0.02, 7);
    default:
        CHECK_STATUS(fl_read_mesh(FL_SOURCE_DIR "/data/demo/torus.off", &m, &err), FL_OK, &err);
        return m;
    }
}

/* Area-weighted normals computed here, independently of the library (§9.4 method 1). */
static void oracle_normals(const fl_mesh *m, double *n)
{
    memset(n, 0, m->vertex_count * 3 * sizeof(double));
    for (size_t t = 0; t < m->triangle_count; t++) {
        const double *a = m->xyz + 3 * m->tri[3 * t], *b = m->xyz + 3 * m->tri[3 * t + 1];
        const double *c = m->xyz + 3 * m->tri[3 * t + 2];
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double x[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]};
        for (int k = 0; k < 3; k++)
            for (int d = 0; d < 3; d++)
                n[3 * m->tri[3 * t + k] + d] += x[d];
    }
    for (size_t i = 0; i < m->vertex_count; i++) {
        double *p = n + 3 * i, l = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (int d = 0; d < 3; d++)
            p[d] /= l;
    }
}

static void test_g1_surfaces_interpolate_vertices_and_normals_to_1e12(void)
{
    for (int scheme = 0; scheme < 2; scheme++)
        for (int i = 0; i < MESHES; i++) {
            fl_mesh m = test_mesh(i);
            fl_g1_surface s;
            fl_error err;
            fl_g1_surface_options o = {.scheme = scheme};
            CHECK_STATUS(fl_g1_surface_build(&m, &o, &s, &err), FL_OK, &err);
            double *n = malloc(m.vertex_count * 3 * sizeof(double));
            oracle_normals(&m, n);
            double verr = 0, nerr = 0;
            size_t corners = 0;
            for (size_t p = 0; p < s.patch_count; p++)
                for (int c = 0; c < 3; c++) {
                    uint32_t v = s.corner[3 * p + c];
                    if (v >= m.vertex_count) continue;
                    double bc[3] = {c == 0, c == 1, c == 2}, pt[3], nn[3];
                    fl_g1_patch_eval(s.ctrl + 30 * p, bc[0], bc[1], bc[2], pt, nn);
                    for (int d = 0; d < 3; d++) {
                        verr = fmax(verr, fabs(pt[d] - m.xyz[3 * v + d]));
                        /* repaired normals are not the estimate; none is repaired here */
                        nerr = fmax(nerr, fabs(nn[d] - n[3 * v + d]));
                    }
                    corners++;
                }
            CHECK_EQ_INT(s.orientation_repairs, 0);
            CHECK_MSG(verr <= 1e-12 && nerr <= 1e-12, "mesh %d scheme %d: %g %g", i, scheme, verr,
                      nerr);
            CHECK(corners >= m.vertex_count);
            free(n);
            fl_g1_surface_free(&s);
            fl_mesh_free(&m);
        }
}

static void test_g1_three_split_normals_agree_along_every_micro_and_macro_edge(void)
{
    for (int i = 0; i < MESHES; i++) {
        fl_mesh m = test_mesh(i);
        fl_g1_surface s;
        fl_error err;
        CHECK_STATUS(fl_g1_surface_build(&m, NULL, &s, &err), FL_OK, &err);
        size_t flips, unpaired;
        double jump = g1_max_edge_jump(&s, 32, &flips, &unpaired);
        CHECK_MSG(jump < 1e-7, "mesh %d: normal jump %g degrees", i, jump);
        CHECK_EQ_INT(flips, 0);
        CHECK_EQ_INT(unpaired, 0);
        CHECK_EQ_INT(s.patch_count, 3 * m.triangle_count);
        /* the library's own measure agrees with this independent one */
        fl_g1_metrics mt;
        CHECK_STATUS(fl_g1_surface_measure(&s, &m, 8, &mt, &err), FL_OK, &err);
        CHECK(mt.max_edge_normal_jump_deg < 1e-7 && mt.orientation_flips == 0);
        CHECK(mt.max_deviation > 0 && mt.max_deviation < 0.5);
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
}

static void test_g1_macro_scheme_is_pn_triangles_and_only_c0(void)
{
    for (int i = 0; i < MESHES; i++) {
        fl_mesh m = test_mesh(i);
        fl_g1_surface s;
        fl_error err;
        fl_g1_surface_options o = {.scheme = FL_G1_MACRO};
        CHECK_STATUS(fl_g1_surface_build(&m, &o, &s, &err), FL_OK, &err);
        double worst = 0, pn[30];
        for (size_t t = 0; t < m.triangle_count; t++) {
            const uint32_t *v = m.tri + 3 * t;
            g1_pn_control_points(m.xyz + 3 * v[0], m.xyz + 3 * v[1], m.xyz + 3 * v[2],
                                 s.normal + 3 * v[0], s.normal + 3 * v[1], s.normal + 3 * v[2], pn);
            for (int k = 0; k < 30; k++)
                worst = fmax(worst, fabs(pn[k] - s.ctrl[30 * t + k]));
        }
        CHECK_MSG(worst < 1e-14, "mesh %d: macro patch differs from PN by %g", i, worst);
        size_t flips, unpaired;
        double jump = g1_max_edge_jump(&s, 32, &flips, &unpaired);
        CHECK_MSG(jump > 0.1, "mesh %d: PN jump %g (PN triangles are only C0)", i, jump);
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
}

static void test_g1_tessellation_is_closed_manifold_and_keeps_genus(void)
{
    for (int i = 0; i < MESHES; i++) {
        fl_mesh m = test_mesh(i), tm;
        fl_g1_surface s;
        fl_error err;
        double *n = NULL;
        CHECK_STATUS(fl_g1_surface_build(&m, NULL, &s, &err), FL_OK, &err);
        unsigned density = i == 4 ? 3 : 5;
        CHECK_STATUS(fl_g1_surface_tessellate(&s, density, &tm, &n, &err), FL_OK, &err);
        fl_mesh_report r, r0;
        fl_mesh_check_options skip = {.skip_self_intersections = 1};
        CHECK_STATUS(fl_mesh_check(&tm, i == 4 ? &skip : NULL, &r, &err), FL_OK, &err);
        CHECK_STATUS(fl_mesh_check(&m, &skip, &r0, &err), FL_OK, &err);
        CHECK(r.closed && r.manifold && r.oriented);
        CHECK_EQ_INT(r.genus, r0.genus);
        CHECK_EQ_INT(r.duplicate_vertices, 0);
        if (i != 4) CHECK_EQ_INT(r.self_intersections, 0);
        CHECK_EQ_INT(tm.triangle_count, s.patch_count * density * density);
        /* Euler: V = F/2 + 2 - 2g */
        CHECK_EQ_INT((long long)tm.vertex_count,
                     (long long)tm.triangle_count / 2 + 2 - 2 * r0.genus);
        /* every normal is a unit vector facing away from the inside of its triangles */
        double worst = 0;
        for (size_t v = 0; v < tm.vertex_count; v++)
            worst = fmax(worst, fabs(n[3 * v] * n[3 * v] + n[3 * v + 1] * n[3 * v + 1] +
                                     n[3 * v + 2] * n[3 * v + 2] - 1));
        CHECK(worst < 1e-12);
        fl_mesh_report_free(&r);
        fl_mesh_report_free(&r0);
        free(n);
        fl_mesh_free(&tm);
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
}

static void test_g1_vertex_normal_weightings(void)
{
    /* Octahedron: every weighting gives the exact direction of the vertex. */
    fl_mesh m = g1_octahedron();
    double n[18];
    fl_error err;
    for (int w = 0; w <= 3; w++) {
        CHECK_STATUS(fl_g1_vertex_normals(&m, w, n, &err), FL_OK, &err);
        for (int i = 0; i < 18; i++)
            CHECK_NEAR(n[i], m.xyz[i], 1e-15);
    }
    fl_mesh_free(&m);
    /* Cube corner (0,0,0): two triangles on each face; area weighting weighs each face by its
     * area (equal here), uniform weighting counts triangles: the faces x=0 and y=0 and z=0 each
     * touch the corner with 1 or 2 triangles, so the uniform normal tilts. */
    m = g1_cube();
    double a[24], u[24], inv[24];
    CHECK_STATUS(fl_g1_vertex_normals(&m, FL_G1_WEIGHT_SIZE, a, &err), FL_OK, &err);
    CHECK_STATUS(fl_g1_vertex_normals(&m, FL_G1_WEIGHT_UNIFORM, u, &err), FL_OK, &err);
    CHECK_STATUS(fl_g1_vertex_normals(&m, FL_G1_WEIGHT_INVERSE, inv, &err), FL_OK, &err);
    /* corner 0 is in triangles 0,1 (z=0), 4,5 (y=0), 10? count them independently */
    double expect[3] = {0, 0, 0};
    for (size_t t = 0; t < m.triangle_count; t++)
        for (int k = 0; k < 3; k++)
            if (m.tri[3 * t + k] == 0) {
                const double *p = m.xyz + 3 * m.tri[3 * t], *q = m.xyz + 3 * m.tri[3 * t + 1];
                const double *r = m.xyz + 3 * m.tri[3 * t + 2];
                double e1[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
                double e2[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
                double c[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                               e1[0] * e2[1] - e1[1] * e2[0]};
                double l = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
                for (int d = 0; d < 3; d++)
                    expect[d] += c[d] / l; /* uniform: unit normals */
            }
    double l = sqrt(expect[0] * expect[0] + expect[1] * expect[1] + expect[2] * expect[2]);
    for (int d = 0; d < 3; d++)
        CHECK_NEAR(u[d], expect[d] / l, 1e-15);
    /* all triangles of the cube have the same area: the three weightings coincide */
    for (int i = 0; i < 24; i++) {
        CHECK_NEAR(a[i], u[i], 1e-15);
        CHECK_NEAR(inv[i], u[i], 1e-15);
    }
    fl_mesh_free(&m);
}

static void test_g1_rejects_open_and_misoriented_meshes(void)
{
    fl_mesh m = g1_octahedron();
    fl_g1_surface s;
    fl_error err;
    m.triangle_count = 7; /* drop a triangle: open */
    CHECK_STATUS(fl_g1_surface_build(&m, NULL, &s, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "not closed") != NULL);
    m.triangle_count = 8;
    uint32_t x = m.tri[0];
    m.tri[0] = m.tri[1];
    m.tri[1] = x; /* flip one triangle */
    CHECK_STATUS(fl_g1_surface_build(&m, NULL, &s, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "oriented") != NULL);
    m.tri[1] = m.tri[0];
    m.tri[0] = x;
    m.xyz[4] = NAN;
    CHECK_STATUS(fl_g1_surface_build(&m, NULL, &s, &err), FL_ERR_INPUT, &err);
    m.xyz[4] = 0;
    fl_g1_surface_options bad = {.tension = 1.5};
    CHECK_STATUS(fl_g1_surface_build(&m, &bad, &s, &err), FL_ERR_USAGE, &err);
    CHECK(s.patch_count == 0 && s.ctrl == NULL);
    fl_mesh_free(&m);
}

static void test_g1_repaired_normals_make_every_star_project_counterclockwise(void)
{
    /* A rough icosphere (vertices moved by up to 25% of the radius): some area-weighted
     * normals violate the orientation condition; after the repair every star triangle sees
     * its vertex normal from above (exact orient3d on v + normal). */
    size_t repairs = 0;
    for (unsigned long long seed = 1; seed <= 4; seed++) {
        fl_mesh m = g1_icosphere(1, 0.25, seed);
        fl_g1_surface s;
        fl_error err;
        CHECK_STATUS(fl_g1_surface_build(&m, NULL, &s, &err), FL_OK, &err);
        repairs += s.orientation_repairs;
        CHECK_EQ_INT(s.orientation_failures, 0);
        for (size_t t = 0; t < m.triangle_count; t++)
            for (int k = 0; k < 3; k++) {
                uint32_t v = m.tri[3 * t + k];
                const double *p = m.xyz + 3 * v, *n = s.normal + 3 * v;
                double q[3] = {p[0] + n[0], p[1] + n[1], p[2] + n[2]};
                CHECK(fl_orient3d(p, m.xyz + 3 * m.tri[3 * t + (k + 1) % 3],
                                  m.xyz + 3 * m.tri[3 * t + (k + 2) % 3], q) < 0);
            }
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
    CHECK(repairs > 0);
}

static void test_g1_meshed_cube_builds_without_folds(void)
{
    /* Regression: vertices on cube edges have stars seen almost edge-on; a quadratic boundary
     * curve that turned an end tangent too far folded them and eq. 9.3a had no solution. */
    for (int n = 1; n <= 3; n++) {
        fl_mesh m = g1_meshed_cube(n), tm;
        fl_g1_surface s;
        fl_error err;
        double *nn = NULL;
        CHECK_STATUS(fl_g1_surface_build(&m, NULL, &s, &err), FL_OK, &err);
        size_t flips, unpaired;
        double jump = g1_max_edge_jump(&s, 16, &flips, &unpaired);
        CHECK_EQ_INT(flips, 0);
        CHECK_EQ_INT(unpaired, 0);
        /* n = 1 is the 12-triangle cube: G1. Finer grids keep 8.8 degree jumps on some edges
         * (known problem, docs/smooth.md); this only guards against worse. */
        CHECK_MSG(n == 1 ? jump < 1e-7 : jump < 9, "n %d: jump %g", n, jump);
        CHECK_STATUS(fl_g1_surface_tessellate(&s, 3, &tm, &nn, &err), FL_OK, &err);
        fl_mesh_report r;
        CHECK_STATUS(fl_mesh_check(&tm, NULL, &r, &err), FL_OK, &err);
        CHECK(r.closed && r.manifold && r.oriented && r.genus == 0);
        fl_mesh_report_free(&r);
        free(nn);
        fl_mesh_free(&tm);
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
}

static void test_g1_bez_round_trip_is_exact(void)
{
    fl_mesh m = g1_icosphere(1, 0.02, 3);
    fl_g1_surface s, r;
    fl_error err;
    CHECK_STATUS(fl_g1_surface_build(&m, NULL, &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_g1_write_bez("g1_round_trip.bez", &s, &err), FL_OK, &err);
    CHECK_STATUS(fl_g1_read_bez("g1_round_trip.bez", &r, &err), FL_OK, &err);
    CHECK_EQ_INT(r.patch_count, s.patch_count);
    CHECK(r.patch_count == s.patch_count &&
          memcmp(r.ctrl, s.ctrl, s.patch_count * 30 * sizeof(double)) == 0 &&
          memcmp(r.corner, s.corner, s.patch_count * 3 * sizeof(uint32_t)) == 0);
    fl_g1_surface_free(&r);
    FILE *f = fopen("g1_bad.bez", "w");
    fputs("flintstone-bez 1\npatches 1\n0 1 2\n0 0 0\n1 2\n", f);
    fclose(f);
    CHECK_STATUS(fl_g1_read_bez("g1_bad.bez", &r, &err), FL_ERR_INPUT, &err);
    CHECK_EQ_INT(err.line, 5);
    remove("g1_round_trip.bez");
    remove("g1_bad.bez");
    fl_g1_surface_free(&r);
    fl_g1_surface_free(&s);
    fl_mesh_free(&m);
}

FL_TEST_MAIN(FL_TEST_CASE(test_g1_surfaces_interpolate_vertices_and_normals_to_1e12),
             FL_TEST_CASE(test_g1_three_split_normals_agree_along_every_micro_and_macro_edge),
             FL_TEST_CASE(test_g1_macro_scheme_is_pn_triangles_and_only_c0),
             FL_TEST_CASE(test_g1_tessellation_is_closed_manifold_and_keeps_genus),
             FL_TEST_CASE(test_g1_vertex_normal_weightings),
             FL_TEST_CASE(test_g1_rejects_open_and_misoriented_meshes),
             FL_TEST_CASE(test_g1_repaired_normals_make_every_star_project_counterclockwise),
             FL_TEST_CASE(test_g1_meshed_cube_builds_without_folds),
             FL_TEST_CASE(test_g1_bez_round_trip_is_exact))
