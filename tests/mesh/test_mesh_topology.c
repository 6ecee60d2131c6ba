/* Topology and measures of fl_mesh_check on meshes whose answers are known in closed form. */
#include <math.h>

#include "fl_test.h"
#include "mesh_fixtures.h"

static const double pi = 3.14159265358979323846;

static fl_mesh_report check(const fl_mesh *m)
{
    fl_mesh_report rep;
    fl_error err;
    CHECK_STATUS(fl_mesh_check(m, NULL, &rep, &err), FL_OK, &err);
    return rep;
}

static void test_tetrahedron_is_closed_oriented_genus_0(void)
{
    fl_mesh m = fx_tetrahedron();
    fl_mesh_report r = check(&m);
    CHECK_EQ_INT(r.vertices, 4);
    CHECK_EQ_INT(r.faces, 4);
    CHECK_EQ_INT(r.edges, 6);
    CHECK(r.closed && r.manifold && r.oriented);
    CHECK_EQ_INT(r.euler, 2);
    CHECK_EQ_INT(r.components, 1);
    CHECK_EQ_INT(r.component_genus[0], 0);
    CHECK_NEAR(r.volume, 1.0 / 6.0, 1e-15);
    CHECK_NEAR(r.area, 1.5 + sqrt(3.0) / 2.0, 1e-14);
    CHECK_EQ_INT(r.self_intersections, 0);
    CHECK(r.self_intersections_checked);
    fl_mesh_report_free(&r);
    fl_mesh_free(&m);
}

static void test_cube_euler_2_volume_1_area_6(void)
{
    fl_mesh m = fx_cube(0, 0, 0, 1);
    fl_mesh_report r = check(&m);
    CHECK_EQ_INT(r.edges, 18);
    CHECK_EQ_INT(r.euler, 2);
    CHECK_EQ_INT(r.genus, 0);
    CHECK(r.closed && r.manifold && r.oriented);
    CHECK_EQ_INT(r.boundary_edges + r.nonmanifold_edges + r.nonmanifold_vertices, 0);
    CHECK_NEAR(r.volume, 1.0, 1e-15);
    CHECK_NEAR(r.area, 6.0, 1e-15);
    for (int k = 0; k < 3; k++)
        CHECK(r.bbox[k] == 0.0 && r.bbox[3 + k] == 1.0);
    CHECK_EQ_INT(r.degenerate_faces + r.duplicate_vertices + r.unreferenced_vertices, 0);
    CHECK_EQ_INT(r.self_intersections, 0);
    fl_mesh_report_free(&r);
    fl_mesh_free(&m);
}

static void test_cube_far_from_origin_keeps_volume(void)
{
    fl_mesh m = fx_cube(1e6, -2e6, 3e6, 0.5);
    fl_mesh_report r = check(&m);
    CHECK_NEAR(r.volume, 0.125, 1e-9);
    fl_mesh_report_free(&r);
    fl_mesh_free(&m);
}

/* Exact volume of the polyhedral torus: between two meridian planes 2a apart it is the set
 * {(rho cos a, t rho sin a, z) : (rho, z) in the meridian n-gon P, |t| <= 1}, whose volume is
 * sin(2a) * area(P) * centroid_rho(P); P is a regular nv-gon of circumradius r centred at
 * rho = R. Its faces are trapezoids with parallel sides 2 rho_j sin a. */
static void test_torus_genus_1_and_polyhedral_volume(void)
{
    double R = 3.0, r = 1.0;
    size_t nu = 48, nv = 24;
    fl_mesh m = fx_torus(R, r, nu, nv);
    fl_mesh_report rep = check(&m);
    CHECK(rep.closed && rep.manifold && rep.oriented);
    CHECK_EQ_INT(rep.euler, 0);
    CHECK_EQ_INT(rep.components, 1);
    CHECK_EQ_INT(rep.component_genus[0], 1);
    CHECK_EQ_INT(rep.genus, 1);
    double a = pi / (double)nu;
    double area_p = 0.5 * (double)nv * r * r * sin(2 * pi / (double)nv);
    double volume = (double)nu * sin(2 * a) * area_p * R;
    CHECK_NEAR(rep.volume, volume, 1e-12 * volume);
    CHECK_NEAR(rep.volume, 2 * pi * pi * R * r * r, 0.02 * 2 * pi * pi * R * r * r);
    double area = 0.0;
    for (size_t j = 0; j < nv; j++) {
        double v0 = 2 * pi * (double)j / (double)nv, v1 = 2 * pi * (double)(j + 1) / (double)nv;
        double rho0 = R + r * cos(v0), rho1 = R + r * cos(v1);
        double h = hypot((rho1 - rho0) * cos(a), r * (sin(v1) - sin(v0)));
        area += (double)nu * (rho0 + rho1) * sin(a) * h;
    }
    CHECK_NEAR(rep.area, area, 1e-12 * area);
    CHECK_EQ_INT(rep.self_intersections, 0);
    fl_mesh_report_free(&rep);
    fl_mesh_free(&m);
}

/* Removes the quad (i0, j0) of a torus of the fixture layout (its two triangles). */
static void remove_quad(fl_mesh *m, size_t nv, size_t i0, size_t j0)
{
    size_t q = i0 * nv + j0, last = m->triangle_count / 2 - 1;
    memmove(m->tri + 6 * q, m->tri + 6 * (q + 1), 6 * (last - q) * sizeof(uint32_t));
    m->triangle_count -= 2;
}

/* Two tori with one quad removed each, joined by a four-sided tube: chi = -1 - 1 + 0. */
static void test_double_torus_genus_2(void)
{
    size_t nu = 16, nv = 8;
    fl_mesh a = fx_torus(3, 1, nu, nv), b = fx_torus(3, 1, nu, nv);
    for (size_t i = 0; i < b.vertex_count; i++)
        b.xyz[3 * i] += 10.0;
    remove_quad(&a, nv, 0, 0);                                 /* faces +x */
    remove_quad(&b, nv, nu / 2, 0);                            /* faces -x */
    uint32_t la[4] = {0, (uint32_t)nv, (uint32_t)(nv + 1), 1}; /* a's hole, in a's face order */
    size_t i1 = nu / 2 + 1;
    uint32_t lb[4] = {(uint32_t)(nu / 2 * nv), (uint32_t)(i1 * nv), (uint32_t)(i1 * nv + 1),
                      (uint32_t)(nu / 2 * nv + 1)};
    size_t ta = a.triangle_count;
    fl_mesh m = fx_concat(a, b);
    uint32_t off = (uint32_t)(nu * nv);
    m.tri = realloc(m.tri, 3 * (m.triangle_count + 8) * sizeof(uint32_t));
    for (int k = 0; k < 4; k++) {
        /* the tube runs along each hole loop in the removed faces' direction; b's loop is
         * traversed backwards so the tube is a consistently oriented cylinder */
        uint32_t a0 = la[k], a1 = la[(k + 1) % 4];
        uint32_t b0 = lb[(4 - k) % 4] + off, b1 = lb[(4 - k - 1 + 4) % 4] + off;
        uint32_t *t = m.tri + 3 * (m.triangle_count + 2 * (size_t)k);
        t[0] = a0, t[1] = a1, t[2] = b1, t[3] = a0, t[4] = b1, t[5] = b0;
    }
    m.triangle_count += 8;
    (void)ta;
    fl_mesh_check_options opt = {0};
    opt.skip_self_intersections = 1;
    fl_mesh_report r;
    fl_error err;
    CHECK_STATUS(fl_mesh_check(&m, &opt, &r, &err), FL_OK, &err);
    CHECK(r.closed && r.manifold && r.oriented);
    CHECK_EQ_INT(r.components, 1);
    CHECK_EQ_INT(r.euler, -2);
    CHECK_EQ_INT(r.genus, 2);
    CHECK(!r.self_intersections_checked);
    fl_mesh_report_free(&r);
    fl_mesh_free(&m);
}

static void test_disc_is_open_with_nan_volume(void)
{
    fl_mesh m = fx_disc(12);
    fl_mesh_report r = check(&m);
    CHECK(!r.closed && r.manifold && r.oriented);
    CHECK_EQ_INT(r.boundary_edges, 12);
    CHECK_EQ_INT(r.euler, 1);
    CHECK_EQ_INT(r.component_genus[0], -1);
    CHECK(isnan(r.volume));
    CHECK_NEAR(r.area, 0.5 * 12 * sin(2 * pi / 12), 1e-14);
    fl_mesh_report_free(&r);
    fl_mesh_free(&m);
}

static void test_three_triangles_on_one_edge_are_nonmanifold(void)
{
    static const double xyz[] = {0, 0, 0, 0, 0, 1, 1, 0, 0, -1, 0, 0, 0, 1, 0};
    static const uint32_t tri[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    fl_mesh m = fx_from_arrays(xyz, 5, tri, 3);
    fl_mesh_report r = check(&m);
    CHECK_EQ_INT(r.nonmanifold_edges, 1);
    CHECK(!r.manifold && !r.closed);
    CHECK_EQ_INT(r.boundary_edges, 6);
    /* the edge is used twice in the direction 0->1 */
    CHECK_EQ_INT(r.misoriented_edges, 1);
    CHECK_EQ_INT(r.self_intersections, 0);
    fl_mesh_report_free(&r);
    fl_mesh_free(&m);
}

/* Two closed pyramids sharing only their apex vertex index: edge-manifold, closed, but the
 * apex has two fans. */
static void test_cones_touching_at_apex_are_vertex_nonmanifold(void)
{
    size_t n = 6;
    fl_mesh m = fx_mesh_alloc(1 + 2 * n, 2 * (2 * n - 2));
    size_t t = 0;
    for (int s = 0; s < 2; s++) {
        double z = s ? -1.0 : 1.0;
        uint32_t base = (uint32_t)(1 + s * n);
        for (size_t i = 0; i < n; i++) {
            double *p = m.xyz + 3 * (base + i);
            p[0] = cos(2 * pi * (double)i / (double)n), p[1] = sin(2 * pi * (double)i / (double)n);
            p[2] = z;
        }
        for (size_t i = 0; i < n; i++) { /* sides, outward */
            uint32_t a = base + (uint32_t)i, b = base + (uint32_t)((i + 1) % n);
            uint32_t *f = m.tri + 3 * t++;
            if (s == 0)
                f[0] = 0, f[1] = b, f[2] = a;
            else
                f[0] = 0, f[1] = a, f[2] = b;
        }
        for (size_t i = 1; i + 1 < n; i++) { /* base fan, outward */
            uint32_t *f = m.tri + 3 * t++;
            uint32_t b1 = base + (uint32_t)i, b2 = base + (uint32_t)i + 1;
            if (s == 0)
                f[0] = base, f[1] = b1, f[2] = b2;
            else
                f[0] = base, f[1] = b2, f[2] = b1;
        }
    }
    fl_mesh_report r = check(&m);
    CHECK(r.closed && r.oriented && !r.manifold);
    CHECK_EQ_INT(r.nonmanifold_edges, 0);
    CHECK_EQ_INT(r.nonmanifold_vertices, 1);
    CHECK_EQ_INT(r.components, 1);
    CHECK_EQ_INT(r.component_genus[0], -1);
    CHECK_EQ_INT(r.self_intersections, 0);
    /* each pyramid: base area * height / 3 */
    double base = 0.5 * (double)n * sin(2 * pi / (double)n);
    CHECK_NEAR(r.volume, 2 * base / 3, 1e-14);
    fl_mesh_report_free(&r);
    fl_mesh_free(&m);
}

static void test_flipped_face_breaks_orientation(void)
{
    fl_mesh m = fx_cube(0, 0, 0, 1);
    uint32_t x = m.tri[1];
    m.tri[1] = m.tri[2], m.tri[2] = x;
    fl_mesh_report r = check(&m);
    CHECK(r.closed && r.manifold && !r.oriented);
    CHECK_EQ_INT(r.misoriented_edges, 3);
    CHECK(isnan(r.volume));
    CHECK_EQ_INT(r.component_genus[0], -1);
    fl_mesh_report_free(&r);
    fl_mesh_free(&m);
}

static void test_two_cubes_are_two_genus_0_components(void)
{
    fl_mesh m = fx_concat(fx_cube(0, 0, 0, 1), fx_cube(3, 0, 0, 1));
    fl_mesh_report r = check(&m);
    CHECK_EQ_INT(r.components, 2);
    CHECK_EQ_INT(r.component_genus[0], 0);
    CHECK_EQ_INT(r.component_genus[1], 0);
    CHECK_EQ_INT(r.component_faces[0], 12);
    CHECK_EQ_INT(r.component_faces[1], 12);
    CHECK_EQ_INT(r.euler, 4);
    CHECK_NEAR(r.volume, 2.0, 1e-15);
    CHECK_EQ_INT(r.self_intersections, 0);
    fl_mesh_report_free(&r);
    fl_mesh_free(&m);
}

static void test_unreferenced_and_duplicate_vertices_are_counted(void)
{
    fl_mesh c = fx_cube(0, 0, 0, 1);
    fl_mesh m = fx_mesh_alloc(11, 12);
    memcpy(m.xyz, c.xyz, 24 * sizeof(double));
    memcpy(m.tri, c.tri, 36 * sizeof(uint32_t));
    double extra[9] = {1, 1, 1, -0.0, 0, 0, 5, 5, 5}; /* copies of 6 and 0 (with -0), and new */
    memcpy(m.xyz + 24, extra, sizeof extra);
    fl_mesh_report r = check(&m);
    CHECK_EQ_INT(r.unreferenced_vertices, 3);
    CHECK_EQ_INT(r.duplicate_vertices, 2);
    CHECK_EQ_INT(r.euler, 2);
    CHECK(r.closed);
    CHECK(r.bbox[3] == 5.0);
    fl_mesh_report_free(&r);
    fl_mesh_free(&m);
    fl_mesh_free(&c);
}

/* A triangle soup cube (three own vertices per triangle, as STL stores it): open and touching
 * everywhere until welded, then the closed genus-0 cube with no self-intersections. */
static void test_weld_turns_soup_cube_into_closed_cube(void)
{
    fl_mesh c = fx_cube(0, 0, 0, 1);
    fl_mesh soup = fx_mesh_alloc(36, 12);
    for (size_t i = 0; i < 36; i++) {
        memcpy(soup.xyz + 3 * i, c.xyz + 3 * (size_t)c.tri[i], 3 * sizeof(double));
        soup.tri[i] = (uint32_t)i;
    }
    soup.xyz[3 * 35] = -0.0; /* the same position */
    fl_mesh_report r = check(&soup);
    CHECK(!r.closed);
    CHECK_EQ_INT(r.duplicate_vertices, 36 - 8);
    CHECK_EQ_INT(r.components, 12);
    CHECK(r.self_intersections > 0);
    fl_mesh_report_free(&r);
    fl_mesh w;
    fl_error err;
    CHECK_STATUS(fl_mesh_weld(&soup, &w, &err), FL_OK, &err);
    CHECK_EQ_INT(w.vertex_count, 8);
    CHECK_EQ_INT(w.triangle_count, 12);
    r = check(&w);
    CHECK(r.closed && r.manifold && r.oriented);
    CHECK_EQ_INT(r.genus, 0);
    CHECK_EQ_INT(r.self_intersections, 0);
    CHECK_NEAR(r.volume, 1.0, 1e-15);
    fl_mesh_report_free(&r);
    fl_mesh_free(&w);
    soup.tri[4] = 99;
    CHECK_STATUS(fl_mesh_weld(&soup, &w, &err), FL_ERR_INPUT, &err);
    CHECK(w.xyz == NULL);
    fl_mesh_free(&soup);
    fl_mesh_free(&c);
}

static void test_bad_input_is_rejected_and_report_zeroed(void)
{
    fl_mesh m = fx_tetrahedron();
    fl_mesh_report r;
    fl_error err;
    m.tri[5] = 4;
    CHECK_STATUS(fl_mesh_check(&m, NULL, &r, &err), FL_ERR_INPUT, &err);
    CHECK(r.component_genus == NULL && r.faces == 0);
    m.tri[5] = 3;
    m.xyz[4] = NAN;
    CHECK_STATUS(fl_mesh_check(&m, NULL, &r, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_mesh_check(NULL, NULL, &r, &err), FL_ERR_USAGE, &err);
    fl_mesh_report_free(&r);
    fl_mesh_free(&m);
}

static void test_empty_mesh_has_no_components(void)
{
    fl_mesh m = {0, NULL, 0, NULL};
    fl_mesh_report r = check(&m);
    CHECK_EQ_INT(r.components, 0);
    CHECK(!r.closed && r.manifold && r.oriented);
    CHECK_EQ_INT(r.genus, -1);
    fl_mesh_report_free(&r);
}

static int cancel_at_once(void *user, const char *stage, double fraction)
{
    (void)fraction;
    (void)stage;
    return ++*(int *)user >= 2;
}

static void test_progress_can_cancel(void)
{
    fl_mesh m = fx_torus(3, 1, 200, 100);
    int calls = 0;
    fl_mesh_check_options opt = {0};
    opt.progress = cancel_at_once;
    opt.progress_user = &calls;
    fl_mesh_report r;
    fl_error err;
    CHECK_STATUS(fl_mesh_check(&m, &opt, &r, &err), FL_ERR_ALGORITHM, &err);
    CHECK(strcmp(err.message, "cancelled") == 0);
    CHECK(r.component_genus == NULL);
    fl_mesh_free(&m);
}

/* Number of sides (directed when `directed`) of the mesh equal to {a,b} / (a,b). */
static int side_uses(const fl_mesh *m, uint32_t a, uint32_t b, int directed)
{
    int n = 0;
    for (size_t h = 0; h < 3 * m->triangle_count; h++) {
        uint32_t c = m->tri[h], d = m->tri[h % 3 == 2 ? h - 2 : h + 1];
        n += (c == a && d == b) || (!directed && c == b && d == a);
    }
    return n;
}

/* Brute-force fan count at v: triangles at v joined when they share a side through v that
 * has exactly two triangles. */
static int fans_at(const fl_mesh *m, uint32_t v)
{
    int label[64], nt = 0, fans = 0;
    uint32_t at[64];
    for (uint32_t t = 0; t < m->triangle_count && nt < 64; t++)
        for (int k = 0; k < 3; k++)
            if (m->tri[3 * t + k] == v) {
                at[nt] = t, label[nt] = nt, nt++;
                break;
            }
    for (int changed = 1; changed;) {
        changed = 0;
        for (int i = 0; i < nt; i++)
            for (int j = 0; j < nt; j++)
                for (int k = 0; k < 3; k++) {
                    uint32_t w = m->tri[3 * at[i] + k];
                    int in_j = 0;
                    for (int l = 0; l < 3; l++)
                        in_j |= m->tri[3 * at[j] + l] == w;
                    if (i != j && w != v && in_j && side_uses(m, v, w, 0) == 2 &&
                        label[j] > label[i])
                        label[j] = label[i], changed = 1;
                }
    }
    for (int i = 0; i < nt; i++)
        fans += label[i] == i;
    return fans;
}

/* Random small meshes with shared and unused vertices, repeated triangles and non-manifold
 * edges: every topological count equals its definition evaluated by brute force. */
static void test_random_meshes_match_brute_force_definitions(void)
{
    unsigned long long rng = 41;
    for (int trial = 0; trial < 200; trial++) {
        size_t nv = 3 + fl_test_rand_u64(&rng) % 8, nt = 1 + fl_test_rand_u64(&rng) % 12;
        fl_mesh m = fx_mesh_alloc(nv, nt);
        for (size_t i = 0; i < 3 * nv; i++)
            m.xyz[i] = (double)(fl_test_rand_u64(&rng) % 3);
        for (size_t t = 0; t < nt; t++) { /* distinct corners: fans are defined per triangle */
            uint32_t *f = m.tri + 3 * t;
            do {
                for (int k = 0; k < 3; k++)
                    f[k] = (uint32_t)(fl_test_rand_u64(&rng) % nv);
            } while (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]);
        }
        fl_mesh_report r = check(&m);
        size_t edges = 0, boundary = 0, nonmanifold = 0, misoriented = 0, unref = 0, nmv = 0;
        for (uint32_t a = 0; a < nv; a++)
            for (uint32_t b = a; b < nv; b++) {
                int n = side_uses(&m, a, b, 0);
                if (!n) continue;
                edges++;
                boundary += n == 1;
                nonmanifold += n >= 3;
                misoriented +=
                    a == b ? n > 1 : side_uses(&m, a, b, 1) > 1 || side_uses(&m, b, a, 1) > 1;
            }
        for (uint32_t v = 0; v < nv; v++) {
            int f = fans_at(&m, v);
            unref += f == 0;
            nmv += f > 1;
        }
        CHECK_EQ_INT(r.edges, edges);
        CHECK_EQ_INT(r.boundary_edges, boundary);
        CHECK_EQ_INT(r.nonmanifold_edges, nonmanifold);
        CHECK_EQ_INT(r.misoriented_edges, misoriented);
        CHECK_EQ_INT(r.unreferenced_vertices, unref);
        CHECK_EQ_INT(r.nonmanifold_vertices, nmv);
        CHECK_EQ_INT(r.euler, (long long)(nv - unref) - (long long)edges + (long long)nt);
        int label[16], changed = 1;
        size_t components = 0, faces = 0;
        for (size_t t = 0; t < nt; t++)
            label[t] = (int)t;
        while (changed) { /* triangles sharing a vertex take the smaller label */
            changed = 0;
            for (size_t t = 0; t < nt; t++)
                for (size_t u = 0; u < nt; u++)
                    for (int k = 0; k < 9; k++)
                        if (m.tri[3 * t + k / 3] == m.tri[3 * u + k % 3] && label[u] > label[t])
                            label[u] = label[t], changed = 1;
        }
        for (size_t t = 0; t < nt; t++)
            components += label[t] == (int)t;
        CHECK_EQ_INT(r.components, components);
        for (size_t c = 0; c < r.components; c++)
            faces += r.component_faces[c];
        CHECK_EQ_INT(faces, nt);
        fl_mesh_report_free(&r);
        fl_mesh_free(&m);
    }
}

FL_TEST_MAIN(FL_TEST_CASE(test_tetrahedron_is_closed_oriented_genus_0),
             FL_TEST_CASE(test_cube_euler_2_volume_1_area_6),
             FL_TEST_CASE(test_cube_far_from_origin_keeps_volume),
             FL_TEST_CASE(test_torus_genus_1_and_polyhedral_volume),
             FL_TEST_CASE(test_double_torus_genus_2),
             FL_TEST_CASE(test_disc_is_open_with_nan_volume),
             FL_TEST_CASE(test_three_triangles_on_one_edge_are_nonmanifold),
             FL_TEST_CASE(test_cones_touching_at_apex_are_vertex_nonmanifold),
             FL_TEST_CASE(test_flipped_face_breaks_orientation),
             FL_TEST_CASE(test_two_cubes_are_two_genus_0_components),
             FL_TEST_CASE(test_unreferenced_and_duplicate_vertices_are_counted),
             FL_TEST_CASE(test_weld_turns_soup_cube_into_closed_cube),
             FL_TEST_CASE(test_bad_input_is_rejected_and_report_zeroed),
             FL_TEST_CASE(test_empty_mesh_has_no_components),
             FL_TEST_CASE(test_progress_can_cancel),
             FL_TEST_CASE(test_random_meshes_match_brute_force_definitions))
