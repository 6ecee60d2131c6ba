/* 3D constriction (thesis §5.3): the output is checked against independent facts — fl_mesh_check
 * for closedness, manifoldness, orientation and genus; the free faces of the interior
 * tetrahedra recomputed from scratch; the enclosed volume by the divergence theorem; the convex
 * hull volume as an upper bound. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"
#include "recon3_test_util.h"

#define PI 3.14159265358979323846

/* Volume of the convex hull, as the volume of the whole Delaunay tetrahedralization. */
static double hull_volume(const double *xyz, size_t n)
{
    fl_dt3 dt;
    fl_error err;
    double v = 0;
    if (fl_dt3_build(xyz, n, NULL, &dt, &err) != FL_OK) return NAN;
    fl_mesh mesh = {n, (double *)(uintptr_t)xyz, dt.hull_face_count, dt.hull_faces};
    fl_mesh_check_options mopt = {1, NULL, NULL};
    fl_mesh_report rep;
    if (fl_mesh_check(&mesh, &mopt, &rep, &err) == FL_OK) {
        v = rep.volume;
        fl_mesh_report_free(&rep);
    }
    fl_dt3_free(&dt);
    return v;
}

static double *sphere_points(size_t n, double ax, double ay, double az, unsigned long long seed)
{
    double *p = malloc(3 * n * sizeof *p);
    for (size_t i = 0; i < n; i++) {
        double z = 2 * fl_test_rand01(&seed) - 1, phi = 2 * PI * fl_test_rand01(&seed);
        double s = sqrt(1 - z * z);
        p[3 * i] = ax * s * cos(phi);
        p[3 * i + 1] = ay * s * sin(phi);
        p[3 * i + 2] = az * z;
    }
    return p;
}

static void run_and_check(const double *xyz, size_t n, const fl_reconstruct3_options *opt,
                          int expect_all)
{
    fl_reconstruction3 r;
    fl_error err;
    CHECK_STATUS(fl_reconstruct3(xyz, n, opt, &r, &err), FL_OK, &err);
    if (r.tri) {
        double v = check_reconstruction(xyz, n, &r);
        CHECK(v <= hull_volume(xyz, n) * (1 + 1e-12));
        if (expect_all) CHECK_MSG(r.all_on_boundary, "%zu inside: %s", r.points_inside, r.reason);
    }
    fl_reconstruction3_free(&r);
}

static void test_constrict3_tetrahedron_is_its_four_faces(void)
{
    const double p[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    fl_reconstruction3 r;
    fl_error err;
    CHECK_STATUS(fl_reconstruct3(p, 4, NULL, &r, &err), FL_OK, &err);
    CHECK_EQ_INT(r.triangle_count, 4);
    CHECK_EQ_INT(r.tet_count, 1);
    CHECK_EQ_INT(r.removed_count, 0);
    CHECK(r.all_on_boundary);
    CHECK_NEAR(r.volume, 1.0 / 6.0, 1e-15);
    CHECK(isnan(r.augmented_c0));
    check_reconstruction(p, 4, &r);
    fl_reconstruction3_free(&r);
}

static void test_constrict3_random_sphere_is_its_hull(void)
{
    size_t n = 300;
    double *p = sphere_points(n, 1, 1, 1, 11);
    fl_reconstruction3 r;
    fl_error err;
    CHECK_STATUS(fl_reconstruct3(p, n, NULL, &r, &err), FL_OK, &err);
    /* every point of a sphere is on the hull: nothing to remove; Euler: F = 2V - 4 */
    CHECK_EQ_INT(r.removed_count, 0);
    CHECK_EQ_INT(r.triangle_count, 2 * n - 4);
    double v = check_reconstruction(p, n, &r);
    CHECK(v < 4.0 / 3.0 * PI && v > 0.9 * 4.0 / 3.0 * PI);
    fl_reconstruction3_free(&r);
    free(p);
}

/* Integer points with x² + y² + z² = 7² + 4² ... exactly cospherical: the Delaunay
 * tetrahedralization's ties are broken symbolically and the hull is still the answer. */
static void test_constrict3_exact_cospherical_points(void)
{
    double p[3 * 400];
    size_t n = 0;
    for (int x = -9; x <= 9; x++)
        for (int y = -9; y <= 9; y++)
            for (int z = -9; z <= 9; z++)
                if (x * x + y * y + z * z == 81 && n < 400) {
                    p[3 * n] = x;
                    p[3 * n + 1] = y;
                    p[3 * n + 2] = z;
                    n++;
                }
    CHECK(n > 20);
    fl_reconstruction3 r;
    fl_error err;
    CHECK_STATUS(fl_reconstruct3(p, n, NULL, &r, &err), FL_OK, &err);
    CHECK(r.all_on_boundary);
    CHECK_EQ_INT(r.triangle_count, 2 * n - 4);
    check_reconstruction(p, n, &r);
    fl_reconstruction3_free(&r);
}

/* A sphere with points inside: constriction must dig to every one of them. */
static void test_constrict3_sphere_with_inner_points_reaches_all(void)
{
    size_t ns = 200, ni = 5, n = ns + ni;
    double *s = sphere_points(ns, 1, 1, 1, 5);
    double *p = malloc(3 * n * sizeof *p);
    memcpy(p, s, 3 * ns * sizeof *p);
    unsigned long long seed = 99;
    for (size_t i = ns; i < n; i++)
        for (int k = 0; k < 3; k++)
            p[3 * i + k] = 0.6 * (2 * fl_test_rand01(&seed) - 1);
    fl_reconstruct3_options opt = {0};
    run_and_check(p, n, &opt, 0);
    opt.criterion = FL_RECONSTRUCT3_AREA_CHANGE;
    run_and_check(p, n, &opt, 0);
    free(s);
    free(p);
}

static void test_constrict3_ellipsoid(void)
{
    size_t n = 400;
    double *p = sphere_points(n, 3, 1, 0.5, 7);
    run_and_check(p, n, NULL, 1);
    free(p);
}

static void test_constrict3_peanut_from_demo_data(void)
{
    fl_points pts;
    fl_error err;
    CHECK_STATUS(fl_read_points(FL_SOURCE_DIR "/data/demo/peanut.xyz", &pts, &err), FL_OK, &err);
    if (pts.coords) {
        fl_reconstruction3 r;
        CHECK_STATUS(fl_reconstruct3(pts.coords, pts.count, NULL, &r, &err), FL_OK, &err);
        if (r.tri) {
            double v = check_reconstruction(pts.coords, pts.count, &r);
            double hv = hull_volume(pts.coords, pts.count);
            CHECK(v < hv);
            CHECK(r.removed_count > 0);
            CHECK_MSG(r.points_inside * 100 < pts.count, "%zu inside: %s", r.points_inside,
                      r.reason);
            printf("peanut: %zu points, %zu inside, %zu triangles, volume %.4f (hull %.4f)\n",
                   pts.count, r.points_inside, r.triangle_count, v, hv);
        }
        fl_reconstruction3_free(&r);
    }
    fl_points_free(&pts);
}

/* Uniform samples of the surface of two overlapping unit spheres (centres ±0.7 on x): the
 * boundary must follow the analytic surface — no triangle cuts deep into the object (a wrong
 * sign of the γ-indicator digs to depth ~0.4 here) — and enclose about the exact volume of the
 * union, 2 (4π/3) - π (4r + d)(2r - d)² / 12 with r = 1, d = 1.4. */
static void test_constrict3_two_spheres_follow_the_surface(void)
{
    size_t n = 2000, k = 0;
    const double c = 0.7;
    double *p = malloc(3 * n * sizeof *p);
    unsigned long long seed = 77;
    while (k < n) {
        double z = 2 * fl_test_rand01(&seed) - 1, phi = 2 * PI * fl_test_rand01(&seed);
        double s = sqrt(1 - z * z), cx = k % 2 ? c : -c;
        double x = s * cos(phi) + cx, y = s * sin(phi);
        if ((x + cx) * (x + cx) + y * y + z * z < 1) continue; /* inside the other sphere */
        p[3 * k] = x;
        p[3 * k + 1] = y;
        p[3 * k + 2] = z;
        k++;
    }
    fl_reconstruction3 r;
    fl_error err;
    CHECK_STATUS(fl_reconstruct3(p, n, NULL, &r, &err), FL_OK, &err);
    if (r.tri) {
        check_reconstruction(p, n, &r);
        CHECK(r.all_on_boundary);
        double max_depth = 0;
        for (size_t i = 0; i < r.triangle_count; i++) {
            double g[3] = {0, 0, 0};
            for (int v = 0; v < 3; v++)
                for (int a = 0; a < 3; a++)
                    g[a] += p[3 * r.tri[3 * i + v] + a] / 3;
            double d1 = 1 - sqrt((g[0] - c) * (g[0] - c) + g[1] * g[1] + g[2] * g[2]);
            double d2 = 1 - sqrt((g[0] + c) * (g[0] + c) + g[1] * g[1] + g[2] * g[2]);
            max_depth = fmax(max_depth, fmax(d1, d2));
        }
        CHECK_MSG(max_depth < 0.05, "a boundary triangle is %.3f deep inside", max_depth);
        double exact = 8 * PI / 3 - PI * (4 + 2 * c) * (2 - 2 * c) * (2 - 2 * c) / 12;
        CHECK_NEAR(r.volume / exact, 1.0, 0.03);
    }
    fl_reconstruction3_free(&r);
    free(p);
}

static void test_constrict3_cube_surface_samples(void)
{
    size_t per = 60, n = 6 * per;
    double *p = malloc(3 * n * sizeof *p);
    unsigned long long seed = 3;
    for (size_t f = 0; f < 6; f++)
        for (size_t i = 0; i < per; i++) {
            double *q = p + 3 * (f * per + i);
            int axis = (int)(f / 2);
            q[axis] = f % 2 ? 1 : -1;
            q[(axis + 1) % 3] = 2 * fl_test_rand01(&seed) - 1;
            q[(axis + 2) % 3] = 2 * fl_test_rand01(&seed) - 1;
        }
    run_and_check(p, n, NULL, 1);
    free(p);
}

static void test_constrict3_grid_points_result_is_valid(void)
{
    double p[3 * 64];
    size_t n = 0;
    for (int x = 0; x < 4; x++)
        for (int y = 0; y < 4; y++)
            for (int z = 0; z < 4; z++) {
                p[3 * n] = x;
                p[3 * n + 1] = y;
                p[3 * n + 2] = z;
                n++;
            }
    run_and_check(p, n, NULL, 0);
}

static void test_constrict3_duplicates_are_merged(void)
{
    size_t ns = 100, n = ns + 10;
    double *s = sphere_points(ns, 1, 1, 1, 21);
    double *p = malloc(3 * n * sizeof *p);
    memcpy(p, s, 3 * ns * sizeof *p);
    for (size_t i = 0; i < 10; i++)
        memcpy(p + 3 * (ns + i), s + 3 * (7 * i), 3 * sizeof *p);
    fl_reconstruction3 r;
    fl_error err;
    CHECK_STATUS(fl_reconstruct3(p, n, NULL, &r, &err), FL_OK, &err);
    CHECK_EQ_INT(r.unique_count, ns);
    CHECK_EQ_INT(r.point_count, n);
    for (size_t i = 0; i < 3 * r.triangle_count; i++)
        CHECK(r.tri[i] < ns);
    check_reconstruction(p, n, &r);
    fl_reconstruction3_free(&r);
    free(s);
    free(p);
}

/* `extra` goes on removing by the same rule after every point is on the boundary (thesis
 * Fig. 5.5): never more than asked, the volume only shrinks, the boundary stays a sphere. */
static void test_constrict3_extra_removals_keep_a_sphere(void)
{
    fl_points pts;
    fl_error err;
    CHECK_STATUS(fl_read_points(FL_SOURCE_DIR "/data/demo/peanut.xyz", &pts, &err), FL_OK, &err);
    if (!pts.coords) return;
    fl_reconstruct3_options opt = {0};
    fl_reconstruction3 base, more;
    CHECK_STATUS(fl_reconstruct3(pts.coords, pts.count, &opt, &base, &err), FL_OK, &err);
    opt.extra = 50;
    CHECK_STATUS(fl_reconstruct3(pts.coords, pts.count, &opt, &more, &err), FL_OK, &err);
    if (base.tri && more.tri) {
        CHECK_EQ_INT(base.extra_removed, 0);
        CHECK(more.extra_removed <= 50 && more.extra_removed > 0);
        CHECK_EQ_INT(more.removed_count, base.removed_count + more.extra_removed);
        CHECK(more.volume < base.volume);
        CHECK(more.all_on_boundary);
        check_reconstruction(pts.coords, pts.count, &more);
    }
    fl_reconstruction3_free(&base);
    fl_reconstruction3_free(&more);
    fl_points_free(&pts);
}

/* Points filling a flattened ball (not sampled on a surface): constriction of the Delaunay
 * tetrahedralization can lock (thesis §4.3.3). Whatever happens, the result must be a valid
 * sphere, and points left inside must be listed with a reason. */
static void test_constrict3_volume_samples_lock_with_a_reason(void)
{
    size_t n = 512;
    double *p = malloc(3 * n * sizeof *p);
    unsigned long long seed = 11;
    for (size_t i = 0; i < n; i++) {
        double x, y, z;
        do {
            x = 2 * fl_test_rand01(&seed) - 1;
            y = 2 * fl_test_rand01(&seed) - 1;
            z = 2 * fl_test_rand01(&seed) - 1;
        } while (x * x + y * y + z * z > 1);
        p[3 * i] = x;
        p[3 * i + 1] = y;
        p[3 * i + 2] = 0.2 * z;
    }
    fl_reconstruction3 r;
    fl_error err;
    CHECK_STATUS(fl_reconstruct3(p, n, NULL, &r, &err), FL_OK, &err);
    if (r.tri) {
        check_reconstruction(p, n, &r);
        if (r.points_inside) CHECK(strstr(r.reason, "locked") != NULL);
        printf("flattened ball: %zu points, %zu left inside\n", n, r.points_inside);
    }
    fl_reconstruction3_free(&r);
    free(p);
}

static int cancel_in_constriction(void *user, const char *stage, double fraction)
{
    (void)fraction;
    *(int *)user += 1;
    return strcmp(stage, "constriction 3d") == 0;
}

/* The progress callback reaches the constriction loop, and a nonzero answer stops it. */
static void test_constrict3_progress_can_cancel(void)
{
    size_t n = 6000;
    double *p = sphere_points(n, 1, 1, 1, 31);
    unsigned long long seed = 5;
    for (size_t i = 0; i < n; i += 3) /* a third inside: thousands of removals */
        for (int k = 0; k < 3; k++)
            p[3 * i + k] *= 0.3 + 0.6 * fl_test_rand01(&seed);
    int calls = 0;
    fl_reconstruct3_options opt = {0};
    opt.progress = cancel_in_constriction;
    opt.progress_user = &calls;
    fl_reconstruction3 r;
    fl_error err;
    CHECK_STATUS(fl_reconstruct3(p, n, &opt, &r, &err), FL_ERR_ALGORITHM, &err);
    CHECK(strstr(err.message, "cancelled") != NULL);
    CHECK(calls > 0);
    CHECK(r.tri == NULL && r.tet == NULL && r.triangle_count == 0);
    free(p);
}

/* Coordinates near the top of the double range overflow every floating construction; the
 * combinatorial decisions still hold, so the result must still be a valid sphere. */
static void test_constrict3_huge_coordinates_still_give_a_sphere(void)
{
    size_t ns = 60, n = ns + 4;
    double *p = sphere_points(n, 1, 1, 1, 41);
    for (size_t i = ns; i < n; i++)
        for (int k = 0; k < 3; k++)
            p[3 * i + k] *= 0.5;
    for (size_t i = 0; i < 3 * n; i++)
        p[i] *= 1e300;
    fl_reconstruction3 r;
    fl_error err;
    CHECK_STATUS(fl_reconstruct3(p, n, NULL, &r, &err), FL_OK, &err);
    fl_mesh mesh = {n, p, r.triangle_count, r.tri};
    fl_mesh_check_options mopt = {1, NULL, NULL};
    fl_mesh_report rep;
    CHECK_STATUS(fl_mesh_check(&mesh, &mopt, &rep, &err), FL_OK, &err);
    CHECK(rep.closed && rep.manifold && rep.oriented);
    CHECK_EQ_INT(rep.genus, 0);
    CHECK_EQ_INT(r.boundary_vertex_count + r.points_inside, n);
    fl_mesh_report_free(&rep);
    fl_reconstruction3_free(&r);
    free(p);
}

static void test_constrict3_bad_input_is_an_error(void)
{
    double flat[3 * 10];
    for (int i = 0; i < 10; i++) {
        flat[3 * i] = i % 3;
        flat[3 * i + 1] = i / 3;
        flat[3 * i + 2] = 0;
    }
    fl_reconstruction3 r;
    fl_error err;
    CHECK_STATUS(fl_reconstruct3(flat, 10, NULL, &r, &err), FL_ERR_ALGORITHM, &err);
    CHECK(r.tri == NULL && r.triangle_count == 0);
    CHECK_STATUS(fl_reconstruct3(NULL, 10, NULL, &r, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_reconstruct3(flat, 3, NULL, &r, &err), FL_ERR_INPUT, &err);
    flat[4] = NAN;
    CHECK_STATUS(fl_reconstruct3(flat, 10, NULL, &r, &err), FL_ERR_INPUT, &err);
    fl_reconstruct3_options opt = {0};
    opt.criterion = (fl_reconstruct3_criterion)7;
    CHECK_STATUS(fl_reconstruct3(flat, 10, &opt, &r, &err), FL_ERR_USAGE, &err);
    fl_reconstruction3_free(&r);
    fl_reconstruction3_free(&r); /* twice is a no-op */
}

FL_TEST_MAIN(FL_TEST_CASE(test_constrict3_tetrahedron_is_its_four_faces),
             FL_TEST_CASE(test_constrict3_random_sphere_is_its_hull),
             FL_TEST_CASE(test_constrict3_exact_cospherical_points),
             FL_TEST_CASE(test_constrict3_sphere_with_inner_points_reaches_all),
             FL_TEST_CASE(test_constrict3_ellipsoid),
             FL_TEST_CASE(test_constrict3_peanut_from_demo_data),
             FL_TEST_CASE(test_constrict3_two_spheres_follow_the_surface),
             FL_TEST_CASE(test_constrict3_cube_surface_samples),
             FL_TEST_CASE(test_constrict3_grid_points_result_is_valid),
             FL_TEST_CASE(test_constrict3_duplicates_are_merged),
             FL_TEST_CASE(test_constrict3_extra_removals_keep_a_sphere),
             FL_TEST_CASE(test_constrict3_volume_samples_lock_with_a_reason),
             FL_TEST_CASE(test_constrict3_progress_can_cancel),
             FL_TEST_CASE(test_constrict3_huge_coordinates_still_give_a_sphere),
             FL_TEST_CASE(test_constrict3_bad_input_is_an_error))
