/* Constrained 3D constriction (thesis §5.7): kept triangles are never deleted. Checked against
 * an unconstrained run on the same points: triangles that run deletes are chosen as kept, and the
 * constrained result must be a valid sphere (recon3_test_util.h) with each kept triangle among
 * its boundary triangles, or keep_missing counting exactly the kept triangles absent from it
 * (recounted here) with a reason. Impossible constraints (not a Delaunay face, looked up in
 * fl_dt3_build's tetrahedra independently) are FL_ERR_INPUT. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"
#include "recon3_test_util.h"

#define PI 3.14159265358979323846

/* 200 points on the unit sphere and 20 inside. */
static double *sample(size_t *n)
{
    size_t ns = 200, ni = 20;
    *n = ns + ni;
    double *p = malloc(3 * *n * sizeof *p);
    unsigned long long seed = 7;
    for (size_t i = 0; i < ns; i++) {
        double z = 2 * fl_test_rand01(&seed) - 1, phi = 2 * PI * fl_test_rand01(&seed);
        p[3 * i] = sqrt(1 - z * z) * cos(phi);
        p[3 * i + 1] = sqrt(1 - z * z) * sin(phi);
        p[3 * i + 2] = z;
    }
    for (size_t i = ns; i < *n; i++)
        for (int k = 0; k < 3; k++)
            p[3 * i + k] = 0.5 * (2 * fl_test_rand01(&seed) - 1);
    return p;
}

static int same_triangle(const uint32_t *a, uint32_t x, uint32_t y, uint32_t z)
{
    int hit = 0;
    for (int i = 0; i < 3; i++)
        hit += a[i] == x || a[i] == y || a[i] == z;
    return hit == 3;
}

static int in_boundary(const fl_reconstruction3 *r, const uint32_t *t)
{
    for (size_t i = 0; i < r->triangle_count; i++)
        if (same_triangle(r->tri + 3 * i, t[0], t[1], t[2])) return 1;
    return 0;
}

/* 1 when x y z is a face of some tetrahedron of the Delaunay tetrahedralization. */
static int is_delaunay_face(const fl_dt3 *dt, uint32_t x, uint32_t y, uint32_t z)
{
    for (size_t t = 0; t < dt->tet_count; t++) {
        const uint32_t *c = dt->tet + 4 * t;
        int hit = 0;
        for (int i = 0; i < 4; i++)
            hit += c[i] == x || c[i] == y || c[i] == z;
        if (hit == 3) return 1;
    }
    return 0;
}

/* Triangles on the boundary when every point is reached but deleted by 300 extra removals:
 * kept, they survive the extra removals (they are never deleted once on the boundary). */
static void test_keep3_deleted_faces_stay_when_kept(void)
{
    size_t n;
    double *p = sample(&n);
    fl_reconstruct3_options opt = {0};
    fl_reconstruction3 base, more, kept;
    fl_error err;
    CHECK_STATUS(fl_reconstruct3(p, n, &opt, &base, &err), FL_OK, &err);
    opt.extra = 300;
    CHECK_STATUS(fl_reconstruct3(p, n, &opt, &more, &err), FL_OK, &err);
    size_t gone = 0;
    for (size_t i = 0; i < base.triangle_count; i++)
        gone += !in_boundary(&more, base.tri + 3 * i);
    CHECK(gone >= 4);
    uint32_t keep[3 * 8];
    size_t kc = 0;
    for (size_t i = 0, j = 0; i < base.triangle_count && kc < 8; i++)
        if (!in_boundary(&more, base.tri + 3 * i) && j++ % (gone / 8 + 1) == 0)
            memcpy(keep + 3 * kc++, base.tri + 3 * i, 3 * sizeof *keep);
    opt.keep = keep;
    opt.keep_count = kc;
    CHECK_STATUS(fl_reconstruct3(p, n, &opt, &kept, &err), FL_OK, &err);
    if (kept.tri) {
        check_reconstruction(p, n, &kept);
        for (size_t i = 0; i < kc; i++)
            CHECK_MSG(in_boundary(&kept, keep + 3 * i), "kept triangle %zu deleted", i);
        CHECK_EQ_INT(kept.keep_missing, 0);
        CHECK(kept.all_on_boundary);
        CHECK(kept.extra_removed > 0);
        printf("kept %zu of %zu deleted triangles: %zu extra removals (free run: %zu)\n", kc, gone,
               kept.extra_removed, more.extra_removed);
    }
    fl_reconstruction3_free(&base);
    fl_reconstruction3_free(&more);
    fl_reconstruction3_free(&kept);
    free(p);
}

/* An interior Delaunay face (with an inside vertex) reaches the boundary when kept, or is
 * reported missing. */
static void test_keep3_interior_face_is_brought_to_the_boundary_or_reported(void)
{
    size_t n;
    double *p = sample(&n);
    fl_dt3 dt;
    fl_error err;
    CHECK_STATUS(fl_dt3_build(p, n, NULL, &dt, &err), FL_OK, &err);
    static const int fc[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};
    uint32_t keep[3];
    int found = 0;
    for (size_t t = 0; t < dt.tet_count && !found; t++)
        for (int k = 0; k < 4 && !found; k++) {
            const uint32_t *c = dt.tet + 4 * t;
            uint32_t f[3] = {c[fc[k][0]], c[fc[k][1]], c[fc[k][2]]};
            if (f[0] >= 200 && f[1] < 200 && f[2] < 200) { /* one inside point */
                memcpy(keep, f, sizeof keep);
                found = 1;
            }
        }
    CHECK(found);
    fl_reconstruct3_options opt = {0};
    opt.keep = keep;
    opt.keep_count = 1;
    fl_reconstruction3 r;
    CHECK_STATUS(fl_reconstruct3(p, n, &opt, &r, &err), FL_OK, &err);
    if (r.tri) {
        check_reconstruction(p, n, &r);
        CHECK_EQ_INT(r.keep_missing, !in_boundary(&r, keep));
        if (r.keep_missing) CHECK(strstr(r.reason, "kept") != NULL);
        printf("interior kept face: missing %zu, %zu inside\n", r.keep_missing, r.points_inside);
    }
    fl_reconstruction3_free(&r);
    fl_dt3_free(&dt);
    free(p);
}

static void test_keep3_impossible_constraints_are_input_errors(void)
{
    size_t n;
    double *p = sample(&n);
    fl_dt3 dt;
    fl_error err;
    CHECK_STATUS(fl_dt3_build(p, n, NULL, &dt, &err), FL_OK, &err);
    uint32_t bad[3] = {0, 1, 2};
    for (uint32_t k = 2; k < n && is_delaunay_face(&dt, 0, 1, k); k++)
        bad[2] = k + 1;
    CHECK(!is_delaunay_face(&dt, bad[0], bad[1], bad[2]));
    fl_reconstruct3_options opt = {0};
    opt.keep = bad;
    opt.keep_count = 1;
    fl_reconstruction3 r;
    CHECK_STATUS(fl_reconstruct3(p, n, &opt, &r, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "not a face of the Delaunay") != NULL);
    CHECK(r.tri == NULL && r.tet == NULL);
    uint32_t out_of_range[3] = {0, 1, (uint32_t)n};
    opt.keep = out_of_range;
    CHECK_STATUS(fl_reconstruct3(p, n, &opt, &r, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "out of range") != NULL);
    uint32_t repeated[3] = {3, 4, 3};
    opt.keep = repeated;
    CHECK_STATUS(fl_reconstruct3(p, n, &opt, &r, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "repeats") != NULL);
    opt.keep = NULL;
    CHECK_STATUS(fl_reconstruct3(p, n, &opt, &r, &err), FL_ERR_USAGE, &err);
    fl_dt3_free(&dt);
    free(p);
}

FL_TEST_MAIN(FL_TEST_CASE(test_keep3_deleted_faces_stay_when_kept),
             FL_TEST_CASE(test_keep3_interior_face_is_brought_to_the_boundary_or_reported),
             FL_TEST_CASE(test_keep3_impossible_constraints_are_input_errors))
